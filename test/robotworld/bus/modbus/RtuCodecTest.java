package robotworld.bus.modbus;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HexFormat;
import org.junit.jupiter.api.Test;

/** CRC, frames and frame lengths against byte sequences published with the Modbus specifications. */
class RtuCodecTest {

    private static byte[] hex(String text) {
        return HexFormat.of().parseHex(text.replace(" ", ""));
    }

    @Test
    void crcMatchesTheSerialLineSpecificationExample() {
        // Modbus over serial line, 6.2.2: frame 02 07 carries CRC 0x1241, sent as 41 12
        assertEquals(0x1241, Crc16.of(hex("02 07"), 0, 2));
        assertTrue(Crc16.isValidFrame(hex("02 07 41 12"), 4));
        assertFalse(Crc16.isValidFrame(hex("02 07 12 41"), 4));
    }

    @Test
    void encodesTheWellKnownReadHoldingRegistersFrame() {
        byte[] frame = new RtuFrame(1, hex("03 00 00 00 0A")).encode();
        assertArrayEquals(hex("01 03 00 00 00 0A C5 CD"), frame);
        RtuFrame decoded = RtuFrame.decode(frame, frame.length);
        assertEquals(1, decoded.address());
        assertArrayEquals(hex("03 00 00 00 0A"), decoded.pdu());
    }

    @Test
    void decodingAFrameWithABadCrcFails() {
        assertThrows(IllegalArgumentException.class, () -> RtuFrame.decode(hex("01 03 00 00 00 0A C5 CE"), 8));
        assertThrows(IllegalArgumentException.class, () -> RtuFrame.decode(hex("01 03"), 2));
    }

    @Test
    void frameRefusesBadAddressesAndEmptyPdus() {
        assertThrows(IllegalArgumentException.class, () -> new RtuFrame(256, hex("03")));
        assertThrows(IllegalArgumentException.class, () -> new RtuFrame(1, new byte[0]));
        assertThrows(IllegalArgumentException.class, () -> new RtuFrame(1, new byte[254]));
    }

    @Test
    void requestLengthsFollowTheFunctionCodes() {
        FrameLength requests = FrameLengths.requests();
        assertEquals(FrameLength.NEED_MORE, requests.of(hex("01"), 1));
        assertEquals(8, requests.of(hex("01 02"), 2));
        assertEquals(8, requests.of(hex("01 06"), 2));
        assertEquals(FrameLength.NEED_MORE, requests.of(hex("01 10 00 00 00"), 5));
        assertEquals(9 + 4, requests.of(hex("01 10 00 00 00 02 04"), 7));
        assertEquals(4, requests.of(hex("01 11"), 2));
        assertEquals(7, requests.of(hex("01 2B 0E"), 3));
        assertEquals(FrameLength.NEED_MORE, requests.of(hex("01 08"), 2), "diagnostics: see below");
        assertEquals(FrameLength.UNKNOWN, requests.of(hex("01 42"), 2));
    }

    @Test
    void responseLengthsFollowTheRequest() {
        FrameLength toRead = FrameLengths.responseTo(Pdus.readInputRegisters(0, 7));
        assertEquals(FrameLength.NEED_MORE, toRead.of(hex("04 04"), 2));
        assertEquals(5 + 14, toRead.of(hex("04 04 0E"), 3));
        assertEquals(5, toRead.of(hex("04 84"), 2), "exception response");
        assertEquals(FrameLength.UNKNOWN, toRead.of(hex("04 03"), 2), "another function: end by silence");
        assertEquals(8, FrameLengths.responseTo(Pdus.writeSingleRegister(0, 1)).of(hex("01 06"), 2));
        assertEquals(8, FrameLengths.responseTo(Pdus.echo(0x1234)).of(hex("01 08"), 2));
        assertEquals(5 + 4, FrameLengths.responseTo(Pdus.reportServerId()).of(hex("01 11 04"), 3));
    }

    @Test
    void deviceIdentificationResponseLengthWalksTheObjects() {
        // 01 2B 0E 01 01 00 00 02 | 00 03 'A' 'B' 'C' | 01 02 'X' 'Y' | CRC
        byte[] frame = new RtuFrame(1, hex("2B 0E 01 01 00 00 02 00 03 41 42 43 01 02 58 59")).encode();
        FrameLength length = FrameLengths.responseTo(Pdus.readDeviceIdentification());
        assertEquals(FrameLength.NEED_MORE, length.of(frame, 7));
        assertEquals(FrameLength.NEED_MORE, length.of(frame, 9));
        assertEquals(FrameLength.NEED_MORE, length.of(frame, 14));
        assertEquals(frame.length, length.of(frame, 15));
        assertEquals(frame.length, length.of(frame, frame.length));
    }

    @Test
    void decodesDeviceIdentificationObjects() {
        // the layout of the specification's example (MODBUS Application Protocol 1.1b3, 6.21), with our objects
        byte[] pdu = hex("2B 0E 01 01 00 00 03 00 04 41 43 4D 45 01 07 31 35 42 36 33 42 32 02 03 31 2E 30");
        DeviceIdentification identification = DeviceIdentification.decode(pdu);
        assertEquals("ACME", identification.vendorName());
        assertEquals("15B63B2", identification.productCode());
        assertEquals("1.0", identification.revision());
        assertThrows(MalformedPduException.class, () -> DeviceIdentification.decode(hex("2B 0E 01 01 00 00 01 00 09 41")));
        assertThrows(MalformedPduException.class, () -> DeviceIdentification.decode(hex("2B 0E 01 01 00 00 00 99")));
        assertThrows(MalformedPduException.class, () -> DeviceIdentification.decode(hex("03 02 00 01")));
    }

    @Test
    void decodesServerIdReportsWithAOneByteIdAndAdditionalData() {
        // libmodbus: ID, run indicator, then "LMB" and its version
        ServerIdReport report = ServerIdReport.decode(hex("11 06 07 FF 4C 4D 42 33"));
        assertArrayEquals(hex("07"), report.serverId());
        assertTrue(report.running());
        assertArrayEquals(hex("4C 4D 42 33"), report.additionalData());
        assertFalse(ServerIdReport.decode(hex("11 02 07 00")).running());
        assertThrows(MalformedPduException.class, () -> ServerIdReport.decode(hex("11 05 07 FF")));
        assertThrows(MalformedPduException.class, () -> ServerIdReport.decode(hex("11 02 07 12")),
                "no byte can be the run indicator");
    }

    @Test
    void decodesServerIdReportsWithAMultiByteIdBeforeTheRunIndicator() {
        // the layout of many stacks (and of pymodbus): an ID of any length, then the run indicator
        ServerIdReport report = ServerIdReport.decode(hex("11 08 31 35 42 36 33 42 32 FF"));
        assertEquals("15B63B2", report.serverIdText());
        assertTrue(report.running());
        assertEquals(0, report.additionalData().length);
        ServerIdReport stopped = ServerIdReport.decode(hex("11 04 79 6F 75 00"));
        assertFalse(stopped.running(), "'malformed status: run indicator 0x79' was the old reading");
        assertEquals("you", stopped.serverIdText());
        assertEquals("01 02", ServerIdReport.decode(hex("11 03 01 02 FF")).serverIdText());
    }

    @Test
    void returnQueryDataRequestsAreFramedWhateverTheirNumberOfWords() {
        FrameLength requests = FrameLengths.requests();
        byte[] three = new RtuFrame(5, Pdus.echo(0x1111, 0x2222, 0x3333)).encode();
        assertEquals(12, three.length);
        for (int have = 2; have < three.length; have++) {
            assertEquals(FrameLength.NEED_MORE, requests.of(three, have), "not complete at " + have);
        }
        assertEquals(12, requests.of(three, 12));
        byte[] twoFrames = new byte[20];
        System.arraycopy(three, 0, twoFrames, 0, 12);
        System.arraycopy(new RtuFrame(5, Pdus.echo(0x4444)).encode(), 0, twoFrames, 12, 8);
        assertEquals(12, requests.of(twoFrames, 20), "the first of two frames that came together");
        assertEquals(8, requests.of(new RtuFrame(5, hex("08 00 01 00 00")).encode(), 4), "other sub-functions: 1 word");
        assertEquals(6 + 3 * 2, FrameLengths.responseTo(Pdus.echo(1, 2, 3)).of(hex("05 08"), 2));
        assertArrayEquals(hex("08 00 00 00 01 00 02"), Pdus.echo(1, 2));
    }

    @Test
    void splitDeviceIdentificationIsDecodedPartByPart() {
        DeviceIdentification.Part first = DeviceIdentification.decodePart(hex("2B 0E 01 01 FF 01 01 00 04 41 43 4D 45"));
        assertTrue(first.moreFollows());
        assertEquals(1, first.nextObjectId());
        assertThrows(MalformedPduException.class,
                () -> DeviceIdentification.decode(hex("2B 0E 01 01 FF 01 01 00 04 41 43 4D 45")),
                "a part is not the whole identification");
        DeviceIdentification.Part second = DeviceIdentification.decodePart(
                hex("2B 0E 01 01 00 00 02 01 07 31 35 42 36 33 42 32 02 03 31 2E 30"));
        assertFalse(second.moreFollows());
        DeviceIdentification whole = DeviceIdentification.of(java.util.List.of(first, second));
        assertEquals("ACME", whole.vendorName());
        assertEquals("15B63B2", whole.productCode());
        assertEquals("1.0", whole.revision());
        assertArrayEquals(hex("2B 0E 01 02"), Pdus.readDeviceIdentification(2));
        assertThrows(MalformedPduException.class,
                () -> DeviceIdentification.decodePart(hex("2B 0E 01 01 12 00 00")), "more follows must be 00 or FF");
    }

    @Test
    void buildsRequestPdusAndDecodesResponses() {
        assertArrayEquals(hex("02 00 00 00 08"), Pdus.readDiscreteInputs(0, 8));
        assertArrayEquals(hex("06 00 01 FC 18"), Pdus.writeSingleRegister(1, -1000 & 0xFFFF));
        assertArrayEquals(hex("10 00 00 00 02 04 00 01 FF FF"), Pdus.writeMultipleRegisters(0, new int[] {1, 0xFFFF}));
        assertArrayEquals(hex("08 00 00 A5 02"), Pdus.echo(0xA502));
        assertArrayEquals(hex("2B 0E 01 00"), Pdus.readDeviceIdentification());
        boolean[] bits = Pdus.decodeBits(hex("02 01 28"), 8);
        assertTrue(bits[3] && bits[5]);
        assertFalse(bits[0] || bits[4]);
        assertArrayEquals(new int[] {0x0102, 0xFFFF}, Pdus.decodeRegisters(hex("04 04 01 02 FF FF"), 2));
        assertEquals(-1000, Pdus.signed(0xFC18));
        assertThrows(MalformedPduException.class, () -> Pdus.decodeRegisters(hex("04 02 01 02"), 2));
        assertThrows(MalformedPduException.class, () -> Pdus.checkEcho(hex("08 00 00 12 34"), hex("08 00 00 12 35")));
        assertThrows(IllegalArgumentException.class, () -> Pdus.readInputRegisters(0, 126));
        assertThrows(IllegalArgumentException.class, () -> Pdus.writeSingleRegister(0, 65536));
    }

    @Test
    void rtuTimingUsesFixedSilencesAbove19200Baud() {
        RtuTiming fast = RtuTiming.of(115_200, 86_806);
        assertEquals(1_750_000, fast.t35Nanos());
        assertEquals(750_000, fast.t15Nanos());
        RtuTiming slow = RtuTiming.of(9600, 1_041_667);
        assertEquals(Math.round(1_041_667 * 3.5), slow.t35Nanos());
        assertEquals(7 * 86_806L, fast.wireNanos(7));
    }
}
