package robotworld.x10;

/** The sixteen X10 house codes A..P with their 4-bit codes. */
public enum HouseCode {
    A, B, C, D, E, F, G, H, I, J, K, L, M, N, O, P;

    /** The 4-bit code sent on the power line and in CM11A frames. */
    public int code() {
        return X10Constants.CODE_TABLE[ordinal()];
    }

    /** The letter, e.g. 'A'. */
    public char letter() {
        return name().charAt(0);
    }

    /**
     * The house code of a letter A..P (either case).
     *
     * @throws IllegalArgumentException for any other character
     */
    public static HouseCode of(char letter) {
        char upper = Character.toUpperCase(letter);
        if (upper < 'A' || upper > 'P') {
            throw new IllegalArgumentException("X10 house codes are A..P, was '" + letter + "'");
        }
        return values()[upper - 'A'];
    }

    /** The house code whose 4-bit code is {@code code} (only the low nibble counts). */
    public static HouseCode ofCode(int code) {
        return values()[X10Constants.unitOfCode(code) - 1];
    }
}
