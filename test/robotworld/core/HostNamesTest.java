package robotworld.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import java.net.InetAddress;
import java.net.UnknownHostException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/** This computer's name: the resolver's, else the kernel's, so that two computers never both become "localhost". */
class HostNamesTest {

    @Test
    void theResolversNameWhenItResolvesElseTheKernels() throws Exception {
        String expected;
        try {
            expected = InetAddress.getLocalHost().getHostName();
        } catch (UnknownHostException e) { // a machine whose own name is not in /etc/hosts
            expected = HostNames.unresolvedName();
        }
        assertEquals(expected, HostNames.thisComputer());
        assertFalse(HostNames.thisComputer().isBlank());
    }

    @Test
    void withoutTheResolverTheKernelsNameIsUsed() throws Exception {
        Path kernel = Path.of("/proc/sys/kernel/hostname");
        if (Files.isReadable(kernel)) {
            assertEquals(Files.readString(kernel).strip(), HostNames.unresolvedName());
        }
        assertFalse(HostNames.unresolvedName().isBlank());
    }
}
