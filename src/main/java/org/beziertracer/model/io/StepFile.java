package org.beziertracer.model.io;

import java.io.IOException;
import java.io.InterruptedIOException;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import ch.randelshofer.fastdoubleparser.JavaDoubleParser;

/**
 * The entity table of a STEP file in its clear-text encoding (ISO 10303-21): the data sections'
 * entity instances {@code #12=NAME(…);} and complex instances {@code #12=(A(…)B(…));}, each with
 * its line and its parameters as values:
 *
 * <pre>
 * real 1.5, 1.E-3     → Double          integer 7          → Long
 * 'it''s'             → String (quotes undone; \X2\…\X0\ kept raw)
 * .T. .MILLI.         → Enum("T"), Enum("MILLI")
 * #5                  → Ref(5)          (1., #3)           → List
 * $                   → UNSET           *                  → DERIVED
 * LENGTH_MEASURE(1.)  → Typed("LENGTH_MEASURE", 1.0)
 * </pre>
 * Comments {@code /* … *}{@code /} are skipped anywhere outside strings; the header section is
 * checked for its syntax and otherwise ignored. Reads the text once, character by character, and
 * checks the thread's interrupt flag every 4,096 entities. A syntax error, a duplicate entity
 * number, a file larger than {@link ReadLimits#bytesInMemory()} or a token longer than
 * {@link ReadLimits#lineChars()} is one line naming the file and the line.
 *
 * <p>Reference: ISO 10303-21:2016, <i>Clear text encoding of the exchange structure</i>, §6–§12.
 */
final class StepFile {

    /** A reference to entity {@code #id}. */
    record Ref(int id) { }

    /** An enumeration or logical value, without its dots: {@code .T.} → {@code T}. */
    record Enum(String name) { }

    /** A typed parameter {@code NAME(value)} (a select type's value). */
    record Typed(String type, Object value) { }

    /** The omitted parameter {@code $}. */
    static final Object UNSET = new Object() {
        @Override
        public String toString() { return "$"; }
    };

    /** A derived parameter {@code *}. */
    static final Object DERIVED = new Object() {
        @Override
        public String toString() { return "*"; }
    };

    /** One record of an instance: its type name and its parameters. */
    record Part(String type, List<Object> params) { }

    /** One entity instance: a simple one has one part, a complex one several (in the file's order). */
    record Entity(int id, int line, List<Part> parts) {

        boolean complex() { return parts.size() > 1; }

        /** The type of a simple instance, or the parts' types joined by {@code +} for a complex one. */
        String type() {
            if (parts.size() == 1) {
                return parts.get(0).type();
            }
            StringBuilder sb = new StringBuilder();
            for (Part p : parts) {
                sb.append(sb.length() == 0 ? "" : "+").append(p.type());
            }
            return sb.toString();
        }

        /** The part of type {@code type}, or null. */
        Part part(String type) {
            for (int k = 0, n = parts.size(); k < n; k++) { // no iterator: called for every entity, often
                Part p = parts.get(k);
                String t = p.type();
                if (t == type || t.equals(type)) {
                    return p;
                }
            }
            return null;
        }

        /** Whether the instance is of {@code type} (a simple one) or has a part of it (a complex one). */
        boolean is(String type) {
            return part(type) != null;
        }
    }

    /** Deepest nesting of lists and typed parameters. */
    static final int MAX_DEPTH = 32;

    final TextSource source;
    final Map<Integer, Entity> entities = new HashMap<>();
    final List<Entity> order = new ArrayList<>();
    /** The header's FILE_SCHEMA names, for messages. */
    final List<String> schemas = new ArrayList<>();

    private int c = -2; // the current character; -2 before the first
    private int line = 1;
    private long chars;
    private final long maxChars;
    private final int maxToken;

    private StepFile(TextSource source) {
        this.source = source;
        this.maxChars = source.limits().bytesInMemory();
        this.maxToken = source.limits().lineChars();
    }

    /** Reads and checks the whole file. */
    static StepFile read(TextSource source) throws IOException {
        StepFile f = new StepFile(source);
        f.parse();
        return f;
    }

    /** The entity {@code ref} refers to; a missing one is an error naming {@code from}. */
    Entity resolve(Ref ref, Entity from) {
        Entity e = entities.get(ref.id());
        if (e == null) {
            throw source.error(from.line(), "#" + from.id() + " (" + from.type() + ") refers to #" + ref.id()
                    + ", which the file does not define");
        }
        return e;
    }

    // ---- characters

    /** Characters taken from the source a buffer at a time: an array access a character, not a call chain. */
    private final char[] buffer = new char[1 << 13];
    private int at, end;
    /** The line of the next character (lines end in LF, CRLF or a lone CR, as {@link TextSource} counts them). */
    private int nextLine = 1;
    private boolean afterCr;

    private void next() throws IOException {
        if (at == end) {
            end = Math.max(0, source.read(buffer));
            at = 0;
        }
        if (at < end) {
            c = buffer[at++];
            // a line break belongs to the line it ends
            line = nextLine;
            if (c == '\n') {
                if (afterCr) {
                    line = nextLine - 1; // the LF of a CRLF: the line the CR ended
                } else {
                    nextLine++;
                }
                afterCr = false;
            } else if (c == '\r') {
                nextLine++;
                afterCr = true;
            } else {
                afterCr = false;
            }
        } else {
            c = -1;
            line = nextLine;
        }
        if (++chars > maxChars) {
            throw source.error(0, "the file holds more than the " + (maxChars >> 20) + " MB a STEP file may hold");
        }
    }

    /** Skips blanks, line breaks and comments. */
    private void skipSpace() throws IOException {
        while (true) {
            while (c == ' ' || c == '\n' || c == '\r' || c == '\t' || c == '\f') {
                next();
            }
            if (c != '/') {
                return;
            }
            int at = line;
            next();
            if (c != '*') {
                throw source.error(at, "expected a comment /* … */, found " + Echo.quote("/" + (c < 0 ? "" : (char) c)));
            }
            next();
            int last = 0;
            while (!(last == '*' && c == '/')) {
                if (c < 0) {
                    throw source.error(at, "a comment /* … */ that never ends");
                }
                last = c;
                next();
            }
            next();
        }
    }

    private ModelFormatException unexpected(String expected) {
        String found = c < 0 ? "the end of the file" : Echo.quote(String.valueOf((char) c));
        return source.error(line, "expected " + expected + ", found " + found);
    }

    /** {@link #expect(char, String)} whose message names the entity {@code #id}: no text made unless it fails. */
    private void expect(char ch, String before, int id) throws IOException {
        skipSpace();
        if (c != ch) {
            throw unexpected("'" + ch + "'" + before + id);
        }
        next();
    }

    private void expect(char ch, String where) throws IOException {
        skipSpace();
        if (c != ch) {
            throw unexpected("'" + ch + "'" + where);
        }
        next();
    }

    /** A keyword (entity or section name, letters, digits, '_' and '-'), upper case as written. */
    /** The names read so far, each once, as the JVM's interned strings (the types' literals in the code are the same objects). */
    private final Map<String, String> names = new HashMap<>();
    private char[] keywordText = new char[64];

    /**
     * A name; one string object per distinct name, the interned one, so entities share their
     * type names and {@link Entity#is} meets the code's literals by identity.
     */
    private String keyword() throws IOException {
        skipSpace();
        char[] text = keywordText;
        int n = 0;
        while ((c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-' || (c >= 'a' && c <= 'z')
                || (c > 127 && Character.isLetterOrDigit(c))) {
            if (n == maxToken) {
                throw source.error(line, "a name longer than " + maxToken + " characters");
            }
            if (n == text.length) {
                text = keywordText = java.util.Arrays.copyOf(text, Math.min(2 * n, maxToken));
            }
            text[n++] = (char) c;
            next();
        }
        String name = new String(text, 0, n);
        String known = names.get(name);
        if (known == null) {
            known = names.size() < 100_000 ? name.intern() : name; // a file of endless made-up names interns no more
            names.put(known, known);
        }
        return known;
    }

    // ---- structure

    private void parse() throws IOException {
        next();
        if (!"ISO-10303-21".equals(keyword())) {
            throw source.error(line, "not a STEP file: it does not start with ISO-10303-21;");
        }
        expect(';', " after ISO-10303-21");
        if (!"HEADER".equals(keyword())) {
            throw source.error(line, "expected the HEADER; section after ISO-10303-21;");
        }
        expect(';', " after HEADER");
        while (true) {
            int at = line;
            String name = keyword();
            if (name.equals("ENDSEC")) {
                expect(';', " after ENDSEC");
                break;
            }
            if (name.isEmpty()) {
                throw unexpected("a header entity or ENDSEC");
            }
            List<Object> params = params(at, 0);
            expect(';', " after a header entity");
            if (name.equals("FILE_SCHEMA") && !params.isEmpty() && params.get(0) instanceof List<?> l) {
                for (Object o : l) {
                    if (o instanceof String s) {
                        schemas.add(s);
                    }
                }
            }
        }
        int sections = 0;
        while (true) {
            String name = keyword();
            if (name.equals("END-ISO-10303-21")) {
                expect(';', " after END-ISO-10303-21");
                break;
            }
            if (!name.equals("DATA")) {
                throw name.isEmpty() ? unexpected("DATA; or END-ISO-10303-21;")
                        : source.error(line, "expected DATA; or END-ISO-10303-21;, found " + Echo.quote(name));
            }
            skipSpace();
            if (c == '(') {
                params(line, 0); // a named data section's (name, schema)
            }
            expect(';', " after DATA");
            sections++;
            data();
        }
        if (sections == 0) {
            throw source.error(line, "a STEP file without a DATA section");
        }
    }

    /** Entity instances up to ENDSEC. */
    private void data() throws IOException {
        while (true) {
            skipSpace();
            if (c != '#') {
                int at = line;
                String name = keyword();
                if (name.equals("ENDSEC")) {
                    expect(';', " after ENDSEC");
                    return;
                }
                throw source.error(at, "expected an entity instance #N=…; or ENDSEC;, found "
                        + (name.isEmpty() ? (c < 0 ? "the end of the file" : Echo.quote(String.valueOf((char) c)))
                        : Echo.quote(name)));
            }
            int at = line;
            next();
            int id = number();
            expect('=', " after #", id);
            skipSpace();
            List<Part> parts = new ArrayList<>(1);
            if (c == '(') {
                next();
                while (true) {
                    skipSpace();
                    if (c == ')') {
                        next();
                        break;
                    }
                    String type = keyword();
                    if (type.isEmpty()) {
                        throw unexpected("an entity name in the complex instance #" + id);
                    }
                    parts.add(new Part(type, params(line, 0)));
                }
                if (parts.isEmpty()) {
                    throw source.error(at, "#" + id + ": a complex instance without records");
                }
            } else {
                String type = keyword();
                if (type.isEmpty()) {
                    throw unexpected("an entity name after #" + id + "=");
                }
                parts.add(new Part(type, params(at, 0)));
            }
            expect(';', " after the entity #", id);
            Entity e = new Entity(id, at, List.copyOf(parts));
            if (entities.putIfAbsent(id, e) != null) {
                throw source.error(at, "#" + id + " is defined twice (first on line " + entities.get(id).line() + ")");
            }
            order.add(e);
            if ((order.size() & 4095) == 0 && Thread.currentThread().isInterrupted()) {
                throw new InterruptedIOException("the read was cancelled");
            }
        }
    }

    /** An entity number after '#'. */
    private int number() throws IOException {
        long n = 0;
        int digits = 0;
        while (c >= '0' && c <= '9') {
            n = n * 10 + (c - '0');
            if (n > Integer.MAX_VALUE) {
                throw source.error(line, "an entity number larger than " + Integer.MAX_VALUE);
            }
            digits++;
            next();
        }
        if (digits == 0) {
            throw unexpected("an entity number after '#'");
        }
        return (int) n;
    }

    /** A parenthesised parameter list. */
    private List<Object> params(int at, int depth) throws IOException {
        if (depth > MAX_DEPTH) {
            throw source.error(line, "parameters nested more than " + MAX_DEPTH + " deep");
        }
        expect('(', "");
        List<Object> out = new ArrayList<>();
        skipSpace();
        if (c == ')') {
            next();
            return out;
        }
        while (true) {
            out.add(value(depth));
            skipSpace();
            if (c == ',') {
                next();
            } else if (c == ')') {
                next();
                return out;
            } else {
                throw unexpected("',' or ')' in the parameters that start on line " + at);
            }
        }
    }

    private Object value(int depth) throws IOException {
        skipSpace();
        int at = line;
        switch (c) {
            case '$' -> {
                next();
                return UNSET;
            }
            case '*' -> {
                next();
                return DERIVED;
            }
            case '#' -> {
                next();
                return new Ref(number());
            }
            case '\'' -> {
                return string();
            }
            case '"' -> {
                return binary();
            }
            case '.' -> {
                next();
                String name = keyword();
                if (name.isEmpty() || c != '.') {
                    throw unexpected("an enumeration .NAME.");
                }
                next();
                return new Enum(name);
            }
            case '(' -> {
                return params(at, depth + 1);
            }
            default -> {
                if (c == '+' || c == '-' || (c >= '0' && c <= '9')) {
                    return numberValue();
                }
                if (Character.isLetter(c) || c == '_') {
                    String type = keyword();
                    List<Object> inner = params(at, depth + 1);
                    if (inner.size() != 1) {
                        // the type is not echoed: it may be any name the file holds, of any length
                        throw source.error(at, "expected one value in a typed parameter TYPE(value), found "
                                + inner.size());
                    }
                    return new Typed(type, inner.get(0));
                }
                throw unexpected("a parameter");
            }
        }
    }

    /** The characters of the number being read (one buffer for the whole file). */
    private final char[] numberText = new char[65];

    /**
     * A number: a whole one as a {@code Long}, digit by digit; a real by FastDoubleParser on the
     * buffer, correctly rounded as {@link Double#parseDouble} (Lemire 2021, "Number parsing at a
     * gigabyte per second").
     */
    private Object numberValue() throws IOException {
        char[] text = numberText;
        int n = 0;
        boolean real = false;
        while ((c >= '0' && c <= '9') || c == '+' || c == '-' || c == '.' || c == 'E' || c == 'e') {
            real |= c == '.' || c == 'E' || c == 'e';
            if (n == 64) {
                throw source.error(line, "a number longer than 64 characters");
            }
            text[n++] = (char) c;
            next();
        }
        try {
            if (!real) {
                return NumberText.whole(java.nio.CharBuffer.wrap(text, 0, n));
            }
            double v = JavaDoubleParser.parseDouble(text, 0, n);
            if (!Double.isFinite(v)) {
                throw source.error(line, "the number " + Echo.quote(new String(text, 0, n)) + " is too large");
            }
            return v;
        } catch (NumberFormatException e) {
            throw source.error(line, "expected a number, found " + Echo.quote(new String(text, 0, n)));
        }
    }

    /** A string: {@code ''} is one quote; {@code \\} one backslash; other escapes are kept as written. */
    private String string() throws IOException {
        int at = line;
        next();
        StringBuilder sb = new StringBuilder();
        while (true) {
            if (c < 0) {
                throw source.error(at, "a string that never ends (no closing ')");
            }
            if (c == '\'') {
                next();
                if (c != '\'') {
                    return sb.toString();
                }
            } else if (c == '\\') {
                next();
                if (c != '\\') {
                    sb.append('\\');
                    continue;
                }
            }
            if (c != '\n' && c != '\r') {
                sb.append((char) c); // a line break inside a string is not part of it (§6.4.3)
            }
            if (sb.length() > maxToken) {
                throw source.error(at, "a string longer than " + maxToken + " characters");
            }
            next();
        }
    }

    /** A binary {@code "0A3F"}, kept as its hexadecimal text. */
    private String binary() throws IOException {
        int at = line;
        next();
        StringBuilder sb = new StringBuilder();
        while (c != '"') {
            if (!((c >= '0' && c <= '9') || (c >= 'A' && c <= 'F'))) {
                throw source.error(at, "expected hexadecimal digits in a binary \"…\", found "
                        + (c < 0 ? "the end of the file" : Echo.quote(String.valueOf((char) c))));
            }
            sb.append((char) c);
            if (sb.length() > maxToken) {
                throw source.error(at, "a binary longer than " + maxToken + " characters");
            }
            next();
        }
        next();
        return sb.toString();
    }
}
