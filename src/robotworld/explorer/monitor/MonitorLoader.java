package robotworld.explorer.monitor;

import java.lang.reflect.Constructor;
import java.lang.reflect.InvocationTargetException;
import java.util.Objects;
import robotworld.observe.WorldTap;
import robotworld.space.Capi;

/**
 * Finds and builds the monitor of a module by the naming convention
 * ({@link MonitoredModule#monitorClassName()}), through reflection: a module type that brings its own monitor
 * class (from any jar or source tree on the class path) is monitored without any change to this code. When
 * there is no such class, or it cannot be built, the result is a {@link MissingMonitor} whose panel says which
 * class was looked for and why it is not used, never an exception.
 */
public final class MonitorLoader {

    private final ClassLoader classLoader;

    /** A loader that searches the class path of this class. */
    public MonitorLoader() {
        this(MonitorLoader.class.getClassLoader());
    }

    /** A loader that searches {@code classLoader} (e.g. one that adds plug-in jars). */
    public MonitorLoader(ClassLoader classLoader) {
        this.classLoader = Objects.requireNonNull(classLoader, "classLoader");
    }

    /**
     * The monitor of {@code module}, watching it through {@code space}. Call on the Swing event thread.
     *
     * @return the module's monitor, or a placeholder that explains what is missing
     */
    public Monitor load(MonitoredModule module, Capi space) {
        return load(module, space, null);
    }

    /**
     * The monitor of {@code module}, as one more observer of {@code tap} when its class has a public constructor
     * {@code (MonitoredModule, WorldTap)} (the tap's owner starts it), else watching through {@code space} on its
     * own. Call on the Swing event thread.
     *
     * @param tap the world's shared tap, or null
     * @return the module's monitor, or a placeholder that explains what is missing
     */
    public Monitor load(MonitoredModule module, Capi space, WorldTap tap) {
        String className = module.monitorClassName();
        Class<?> type;
        try {
            type = Class.forName(className, true, classLoader);
        } catch (ClassNotFoundException e) {
            return new MissingMonitor(module, className, "no such class on the class path");
        } catch (LinkageError e) {
            return new MissingMonitor(module, className, "cannot be loaded: " + e);
        }
        if (!Monitor.class.isAssignableFrom(type)) {
            return new MissingMonitor(module, className, "does not implement " + Monitor.class.getName());
        }
        try {
            if (tap != null) {
                try {
                    return (Monitor) type.getConstructor(MonitoredModule.class, WorldTap.class).newInstance(module, tap);
                } catch (NoSuchMethodException e) {
                    // a monitor that watches on its own
                }
            }
            Constructor<?> constructor = type.getConstructor(MonitoredModule.class, Capi.class);
            return (Monitor) constructor.newInstance(module, space);
        } catch (NoSuchMethodException e) {
            return new MissingMonitor(module, className, "has no public constructor (MonitoredModule, Capi)");
        } catch (InvocationTargetException e) {
            return new MissingMonitor(module, className, "failed to start: " + e.getCause());
        } catch (ReflectiveOperationException | RuntimeException e) {
            return new MissingMonitor(module, className, "cannot be created: " + e);
        }
    }
}
