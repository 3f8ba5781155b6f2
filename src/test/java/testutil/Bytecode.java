package testutil;

import java.io.DataInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.util.HashMap;
import java.util.Map;

/**
 * Reads how many bytes of bytecode a compiled method has, from its class file: the JIT inlines a hot
 * method only up to a size (C2's {@code FreqInlineSize}, 325 bytes), which a kernel's tests may hold
 * it to.
 */
public final class Bytecode {
    private Bytecode() {
    }

    /**
     * The length of a method's code, as its class file gives it.
     *
     * @param type       the class
     * @param name       the method's name
     * @param descriptor the method's descriptor, e.g. {@code (D)D}
     * @return the number of bytes of its bytecode
     * @throws IllegalArgumentException when the class has no such method with code
     */
    public static int codeLength(Class<?> type, String name, String descriptor) {
        String file = type.getSimpleName() + ".class";
        try (InputStream stream = type.getResourceAsStream(file)) {
            if (stream == null)
                throw new IllegalArgumentException("no class file " + file);
            DataInputStream in = new DataInputStream(stream);
            in.readInt(); // magic
            in.readInt(); // minor and major versions
            Map<Integer, String> texts = readConstants(in);
            in.skipNBytes(6); // access flags, this class, super class
            in.skipNBytes(2L * in.readUnsignedShort()); // interfaces
            skipMembers(in); // fields
            int methods = in.readUnsignedShort();
            for (int m = 0; m < methods; ++m) {
                in.readUnsignedShort(); // access flags
                boolean wanted = name.equals(texts.get(in.readUnsignedShort()))
                        & descriptor.equals(texts.get(in.readUnsignedShort()));
                int attributes = in.readUnsignedShort();
                for (int a = 0; a < attributes; ++a) {
                    String attribute = texts.get(in.readUnsignedShort());
                    int length = in.readInt();
                    if (wanted && "Code".equals(attribute)) {
                        in.readInt(); // max stack and max locals
                        return in.readInt();
                    }
                    in.skipNBytes(length);
                }
            }
            throw new IllegalArgumentException("no method " + name + descriptor + " with code in " + file);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** {@return the UTF-8 texts of a class file's constant pool, by index; the other entries skipped} */
    private static Map<Integer, String> readConstants(DataInputStream in) throws IOException {
        Map<Integer, String> texts = new HashMap<>();
        int count = in.readUnsignedShort();
        for (int i = 1; i < count; ++i) {
            int tag = in.readUnsignedByte();
            switch (tag) {
                case 1 -> texts.put(i, in.readUTF());
                case 7, 8, 16, 19, 20 -> in.skipNBytes(2);
                case 15 -> in.skipNBytes(3);
                case 3, 4, 9, 10, 11, 12, 17, 18 -> in.skipNBytes(4);
                case 5, 6 -> {
                    in.skipNBytes(8);
                    ++i; // a long or a double takes two entries
                }
                default -> throw new IOException("unknown constant tag " + tag);
            }
        }
        return texts;
    }

    /** Skips a class file's fields: each with its attributes. */
    private static void skipMembers(DataInputStream in) throws IOException {
        int members = in.readUnsignedShort();
        for (int m = 0; m < members; ++m) {
            in.skipNBytes(6); // access flags, name, descriptor
            int attributes = in.readUnsignedShort();
            for (int a = 0; a < attributes; ++a) {
                in.skipNBytes(2);
                in.skipNBytes(in.readInt());
            }
        }
    }
}
