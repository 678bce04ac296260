package robotworld.bus;

import java.lang.reflect.Constructor;
import java.lang.reflect.InvocationTargetException;

/**
 * Creates the hardware proxy for a module class named in a description. Convention: the proxy of
 * {@code <Class>} is {@code robotworld.bus.<Class>Proxy} with a constructor {@code (RS485Bus, int, String)}, so a
 * new module type needs a new class and no change here.
 */
public final class ModuleProxies {

    private ModuleProxies() {
    }

    /**
     * The proxy of a module.
     *
     * @param moduleClass the {@code <Class>} of the description, e.g. "BumperModule"
     * @param address the {@code <NodeNumber>}
     * @param name the {@code <Name>}, for messages (may be null)
     * @throws IllegalArgumentException when no proxy follows the convention for {@code moduleClass}
     */
    public static ModuleProxy create(String moduleClass, RS485Bus bus, int address, String name) {
        String proxyName = ModuleProxies.class.getPackageName() + "." + moduleClass + "Proxy";
        try {
            Class<?> type = Class.forName(proxyName);
            if (!ModuleProxy.class.isAssignableFrom(type)) {
                throw new IllegalArgumentException(proxyName + " is not a ModuleProxy");
            }
            Constructor<?> constructor = type.getConstructor(RS485Bus.class, int.class, String.class);
            return (ModuleProxy) constructor.newInstance(bus, address, name);
        } catch (ClassNotFoundException e) {
            throw new IllegalArgumentException("no hardware proxy for module class '" + moduleClass + "' (expected "
                    + proxyName + ")", e);
        } catch (NoSuchMethodException e) {
            throw new IllegalArgumentException(proxyName + " lacks a constructor (RS485Bus, int, String)", e);
        } catch (InvocationTargetException e) {
            if (e.getCause() instanceof RuntimeException runtime) {
                throw runtime;
            }
            throw new IllegalStateException("cannot create " + proxyName + ": " + e.getCause(), e.getCause());
        } catch (ReflectiveOperationException e) {
            throw new IllegalStateException("cannot create " + proxyName + ": " + e, e);
        }
    }
}
