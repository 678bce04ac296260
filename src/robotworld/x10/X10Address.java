package robotworld.x10;

/**
 * One X10 device address: a house code and a unit 1..16.
 *
 * @param house house code A..P
 * @param unit unit code 1..16
 */
public record X10Address(HouseCode house, int unit) {

    public X10Address {
        if (house == null) {
            throw new IllegalArgumentException("house code is required");
        }
        X10Constants.unitCode(unit); // validates 1..16
    }

    /** The address of house {@code house} (A..P) and unit {@code unit} (1..16). */
    public static X10Address of(char house, int unit) {
        return new X10Address(HouseCode.of(house), unit);
    }

    /**
     * Parses "A3", "p16" and the like.
     *
     * @throws IllegalArgumentException with the reason when the text is not an address
     */
    public static X10Address parse(String text) {
        String trimmed = text == null ? "" : text.trim();
        if (trimmed.length() < 2 || trimmed.length() > 3) {
            throw new IllegalArgumentException("'" + text + "' is not an X10 address like A3 or P16");
        }
        int unit;
        try {
            unit = Integer.parseInt(trimmed.substring(1));
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("'" + text + "' is not an X10 address like A3 or P16");
        }
        return of(trimmed.charAt(0), unit);
    }

    /** The address byte: house code in the high nibble, unit code in the low one. */
    public int code() {
        return house.code() << 4 | X10Constants.unitCode(unit);
    }

    /** The address of an address byte. */
    public static X10Address ofCode(int code) {
        return new X10Address(HouseCode.ofCode(code >> 4), X10Constants.unitOfCode(code));
    }

    @Override
    public String toString() {
        return house.name() + unit;
    }
}
