package robotworld.core;

import java.io.IOException;
import java.net.InetAddress;
import java.net.UnknownHostException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * This computer's name, as participants and answer keys use it. The name the resolver gives, or — on a machine
 * whose own name does not resolve (no entry in {@code /etc/hosts}, a container, a fresh VM) — the kernel's host
 * name. "localhost" is the last resort only: two computers that both called themselves that could take each
 * other's answers.
 */
public final class HostNames {

    private static final Path KERNEL_HOST_NAME = Path.of("/proc/sys/kernel/hostname");

    private HostNames() {
    }

    /** This computer's name; never blank. */
    public static String thisComputer() {
        try {
            return InetAddress.getLocalHost().getHostName();
        } catch (UnknownHostException e) {
            return unresolvedName();
        }
    }

    /** The name the operating system knows this computer by, without asking the resolver. */
    static String unresolvedName() {
        try {
            String kernel = Files.readString(KERNEL_HOST_NAME, StandardCharsets.US_ASCII).strip();
            if (!kernel.isEmpty()) {
                return kernel;
            }
        } catch (IOException | SecurityException e) {
            // not Linux: try the environment
        }
        for (String variable : new String[] {"HOSTNAME", "COMPUTERNAME"}) {
            String value = System.getenv(variable);
            if (value != null && !value.isBlank()) {
                return value.strip();
            }
        }
        return "localhost";
    }
}
