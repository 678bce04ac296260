package robotworld.x10;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;

class UploadDecoderTest {

    private final UploadDecoder decoder = new UploadDecoder();

    @Test
    void b6OnFromARemoteControl() {
        // mask 02: data byte 0 (E9 = B6) is an address, byte 1 (E2 = B On) a function
        List<X10Event> events = decoder.decode(Bytes.of("02 E9 E2"));
        assertEquals(List.of(X10Event.of(HouseCode.B, List.of(6), X10Function.ON)), events);
        assertEquals("B6 On", events.get(0).toString());
    }

    @Test
    void theProtocolTextsExampleTwoAddressesThenBright() {
        List<X10Event> events = decoder.decode(Bytes.of("04 E9 E5 E5 58"));
        assertEquals(1, events.size());
        X10Event event = events.get(0);
        assertEquals(List.of(6, 7), event.units());
        assertEquals(X10Function.BRIGHT, event.function());
        assertEquals(0x58, event.dimLevel());
        assertEquals(42, event.dimPercent());
    }

    @Test
    void addressingSpansUploadsAndRestartsAfterAFunction() {
        assertEquals(List.of(), decoder.decode(Bytes.of("00 66")));              // A1
        assertEquals(List.of(1), decoder.decode(Bytes.of("01 62")).get(0).units()); // A On
        decoder.decode(Bytes.of("00 62"));                                      // A3: new list
        assertEquals(List.of(3), decoder.decode(Bytes.of("01 63")).get(0).units()); // A Off
    }

    @Test
    void houseWideFunctionsNameNoUnits() {
        X10Event event = decoder.decode(Bytes.of("01 26")).get(0); // C All Lights Off
        assertEquals(HouseCode.C, event.house());
        assertEquals(X10Function.ALL_LIGHTS_OFF, event.function());
        assertEquals(List.of(), event.units());
        assertEquals(true, event.concerns(X10Address.of('C', 9)));
    }

    @Test
    void extendedCodeBringsUnitDataAndCommand() {
        X10Event event = decoder.decode(Bytes.of("01 A7 03 20 31")).get(0);
        assertEquals(X10Function.EXTENDED_CODE, event.function());
        assertEquals(List.of(11), event.units());
        assertEquals(0x20, event.extendedData());
        assertEquals(0x31, event.extendedCommand());
    }

    @Test
    void truncatedDimIsDropped() {
        assertEquals(List.of(), decoder.decode(Bytes.of("02 E9 E4")));
    }

    @Test
    void presetDimCarriesItsLevelWhereTheHouseWouldBe() {
        UploadDecoder decoder = new UploadDecoder();
        // A1 addressed, then Preset Dim 1 with nibble 0xF (J): level 15
        List<X10Event> events = decoder.decode(new byte[] {0x02, 0x66, (byte) 0xFA});
        assertEquals(1, events.size());
        assertEquals(HouseCode.A, events.get(0).house());
        assertEquals(List.of(1), events.get(0).units());
        assertEquals(15, events.get(0).dimLevel());
        assertEquals("A1 Preset Dim 1 15/31", events.get(0).toString());
    }
}
