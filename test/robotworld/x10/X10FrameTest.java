package robotworld.x10;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class X10FrameTest {

    @ParameterizedTest
    @CsvSource({"A,1,6", "B,2,E", "C,3,2", "D,4,A", "E,5,1", "F,6,9", "G,7,5", "H,8,D",
        "I,9,7", "J,10,F", "K,11,3", "L,12,B", "M,13,0", "N,14,8", "O,15,4", "P,16,C"})
    void houseAndUnitCodesFollowTheX10Table(char house, int unit, String code) {
        int expected = Integer.parseInt(code, 16);
        assertEquals(expected, HouseCode.of(house).code());
        assertEquals(expected, X10Constants.unitCode(unit));
        assertEquals(unit, X10Constants.unitOfCode(expected));
        assertEquals(HouseCode.of(house), HouseCode.ofCode(expected));
    }

    @Test
    void functionCodesFollowTheX10Table() {
        assertEquals(0x0, X10Function.ALL_UNITS_OFF.code());
        assertEquals(0x2, X10Function.ON.code());
        assertEquals(0x4, X10Function.DIM.code());
        assertEquals(0x6, X10Function.ALL_LIGHTS_OFF.code());
        assertEquals(0xF, X10Function.STATUS_REQUEST.code());
        for (X10Function function : X10Function.values()) {
            assertEquals(function, X10Function.ofCode(function.code()));
        }
    }

    @Test
    void turnA3OnIsTwoFramesWithTheDocumentedChecksums() {
        X10Frame address = X10Frame.address(X10Address.of('A', 3));
        X10Frame on = X10Frame.function(HouseCode.A, X10Function.ON);
        assertEquals("04 62", address.hex());
        assertEquals(0x66, address.checksum());
        assertEquals("06 62", on.hex());
        assertEquals(0x68, on.checksum());
    }

    @Test
    void dimStepsGoIntoTheHeader() {
        // the protocol text's example: A Dim 16/22 is 86 64, checksum EA
        X10Frame dim = X10Frame.function(HouseCode.A, X10Function.DIM, 16);
        assertEquals("86 64", dim.hex());
        assertEquals(0xEA, dim.checksum());
        assertEquals("B6 65", X10Frame.function(HouseCode.A, X10Function.BRIGHT, 22).hex());
    }

    @Test
    void addressWhoseChecksumLooksLikeAPollGetsAHarmlessDimStep() {
        // G1: 04 + 56 = 5A would look like a poll; heyu sends 0C 56 instead
        X10Frame g1 = X10Frame.address(X10Address.of('G', 1));
        assertEquals("0C 56", g1.hex());
        assertEquals(0x62, g1.checksum());
        assertFalse(g1.hasAmbiguousChecksum());
    }

    @Test
    void functionWithoutDimsIsMovedOffThePollValues() {
        // 06 + 54 would be 5A: house G (5) function 4 is Dim, which cannot be moved; take a code that can:
        // 06 + 9F = A5: house F (9), Status Request (F)
        X10Frame statusRequest = X10Frame.function(HouseCode.F, X10Function.STATUS_REQUEST);
        assertEquals("0E 9F", statusRequest.hex());
        assertFalse(statusRequest.hasAmbiguousChecksum());
    }

    @Test
    void dimFramesKeepTheirAmbiguousChecksum() {
        // O Dim by 2 steps: 16 + 44 = 5A; the dim count cannot be changed, the controller copes
        X10Frame dim = X10Frame.function(HouseCode.O, X10Function.DIM, 2);
        assertEquals("16 44", dim.hex());
        assertTrue(dim.hasAmbiguousChecksum());
    }

    @Test
    void extendedFrameCarriesUnitDataAndCommand() {
        X10Frame preset = X10Frame.extended(X10Address.of('D', 11), 0xFF, 0x31);
        assertEquals("07 A7 03 FF 31", preset.hex());
        assertEquals((0x07 + 0xA7 + 0x03 + 0xFF + 0x31) & 0xFF, preset.checksum());
    }

    @Test
    void invalidArgumentsAreRejected() {
        assertThrows(IllegalArgumentException.class, () -> X10Frame.function(HouseCode.A, X10Function.DIM, 23));
        assertThrows(IllegalArgumentException.class, () -> X10Frame.function(HouseCode.A, X10Function.ON, 3));
        assertThrows(IllegalArgumentException.class,
                () -> X10Frame.function(HouseCode.A, X10Function.EXTENDED_CODE));
        assertThrows(IllegalArgumentException.class, () -> X10Address.of('Q', 1));
        assertThrows(IllegalArgumentException.class, () -> X10Address.of('A', 17));
        assertThrows(IllegalArgumentException.class, () -> X10Address.parse("A"));
        assertEquals(X10Address.of('P', 16), X10Address.parse("p16"));
    }

    @Test
    void percentagesBecomeTheNearestOf22Steps() {
        assertEquals(0, DimSteps.ofPercent(0));
        assertEquals(11, DimSteps.ofPercent(50));
        assertEquals(22, DimSteps.ofPercent(100));
        assertEquals(1, DimSteps.ofPercent(3));
        assertEquals(9, DimSteps.ofUploadLevel(88));
        assertEquals(210, DimSteps.toUploadLevel(22));
        assertThrows(IllegalArgumentException.class, () -> DimSteps.ofPercent(101));
        assertThrows(IllegalArgumentException.class, () -> DimSteps.ofPercent(-1));
    }
}
