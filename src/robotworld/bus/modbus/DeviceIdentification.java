package robotworld.bus.modbus;

import java.nio.charset.StandardCharsets;
import java.util.Collections;
import java.util.Map;
import java.util.TreeMap;

/**
 * The basic objects of Read Device Identification (function 0x2B, MEI 0x0E): VendorName (object 0), ProductCode
 * (object 1, our modules' NodeID) and MajorMinorRevision (object 2, the module version).
 *
 * @param objects every object the module sent, by object id
 */
public record DeviceIdentification(Map<Integer, String> objects) {

    public static final int VENDOR_NAME = 0x00;
    public static final int PRODUCT_CODE = 0x01;
    public static final int MAJOR_MINOR_REVISION = 0x02;

    public DeviceIdentification {
        objects = Collections.unmodifiableMap(new TreeMap<>(objects));
    }

    /** VendorName, or "" when absent. */
    public String vendorName() {
        return objects.getOrDefault(VENDOR_NAME, "");
    }

    /** ProductCode: the module's NodeID; "" when absent. */
    public String productCode() {
        return objects.getOrDefault(PRODUCT_CODE, "");
    }

    /** MajorMinorRevision: the module's version; "" when absent. */
    public String revision() {
        return objects.getOrDefault(MAJOR_MINOR_REVISION, "");
    }

    /**
     * One transaction's share of the identification: a device whose objects do not fit one response sends
     * "more follows" (0xFF) and the object id to ask for next.
     *
     * @param objects the objects of this response, by object id
     * @param moreFollows whether more objects are to be asked for
     * @param nextObjectId where the next request starts (meaningful when more follows)
     */
    public record Part(Map<Integer, String> objects, boolean moreFollows, int nextObjectId) {
        public Part {
            objects = Collections.unmodifiableMap(new TreeMap<>(objects));
        }
    }

    /** The identification made of several parts, in the order they came (a later object id replaces nothing). */
    public static DeviceIdentification of(Iterable<Part> parts) {
        Map<Integer, String> objects = new TreeMap<>();
        for (Part part : parts) {
            part.objects().forEach(objects::putIfAbsent);
        }
        return new DeviceIdentification(objects);
    }

    /**
     * Decodes a complete response PDU (one that does not announce more objects).
     *
     * @throws MalformedPduException when the layout is broken or more objects follow
     */
    public static DeviceIdentification decode(byte[] pdu) {
        Part part = decodePart(pdu);
        if (part.moreFollows()) {
            throw new MalformedPduException("device identification continues at object " + part.nextObjectId()
                    + " in another transaction");
        }
        return new DeviceIdentification(part.objects());
    }

    /**
     * Decodes one response PDU: {@code 2B 0E code conformity more next count (id len value)*}.
     *
     * @throws MalformedPduException when the layout is broken
     */
    public static Part decodePart(byte[] pdu) {
        if (pdu.length < 7 || (pdu[0] & 0xFF) != FunctionCodes.ENCAPSULATED_INTERFACE
                || (pdu[1] & 0xFF) != FunctionCodes.MEI_READ_DEVICE_ID) {
            throw new MalformedPduException("not a device identification response: " + RtuFrame.hex(pdu, pdu.length));
        }
        int more = pdu[4] & 0xFF;
        if (more != 0x00 && more != 0xFF) {
            throw new MalformedPduException(String.format("device identification 'more follows' is 0x%02X, neither "
                    + "0x00 nor 0xFF", more));
        }
        int count = pdu[6] & 0xFF;
        Map<Integer, String> objects = new TreeMap<>();
        int position = 7;
        for (int i = 0; i < count; i++) {
            if (position + 2 > pdu.length) {
                throw new MalformedPduException("device identification ends inside object " + i);
            }
            int id = pdu[position] & 0xFF;
            int length = pdu[position + 1] & 0xFF;
            if (position + 2 + length > pdu.length) {
                throw new MalformedPduException("device identification object " + id + " is cut short");
            }
            // the standard objects are ASCII strings
            objects.put(id, new String(pdu, position + 2, length, StandardCharsets.ISO_8859_1));
            position += 2 + length;
        }
        if (position != pdu.length) {
            throw new MalformedPduException("device identification has " + (pdu.length - position)
                    + " bytes after its last object");
        }
        return new Part(objects, more == 0xFF, pdu[5] & 0xFF);
    }
}
