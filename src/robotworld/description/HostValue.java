package robotworld.description;

/**
 * A {@code <Host>} as written: a host name or address ({@code robot-laptop}, {@code 192.168.1.20},
 * {@code [::1]}), or a URL that names the host ({@code http://robot-laptop:8080/}, as the thesis writes hosts).
 */
public final class HostValue {

    private HostValue() {
    }

    /** The host name: the value itself, or the host part of a URL (without brackets for IPv6, no port). */
    public static String hostName(String host) {
        String value = host.strip();
        int scheme = value.indexOf("://");
        if (scheme < 0) {
            return value;
        }
        String rest = value.substring(scheme + 3);
        int slash = rest.indexOf('/');
        String authority = slash < 0 ? rest : rest.substring(0, slash);
        if (authority.startsWith("[")) {
            int close = authority.indexOf(']');
            return close < 0 ? authority : authority.substring(0, close + 1);
        }
        int colon = authority.indexOf(':');
        return colon < 0 ? authority : authority.substring(0, colon);
    }
}
