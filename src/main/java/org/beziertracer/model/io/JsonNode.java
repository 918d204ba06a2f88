package org.beziertracer.model.io;

import java.io.EOFException;
import java.io.IOException;
import java.io.StringReader;
import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonNull;
import com.google.gson.JsonObject;
import com.google.gson.JsonPrimitive;
import com.google.gson.Strictness;
import com.google.gson.stream.JsonReader;
import com.google.gson.stream.JsonToken;
import com.google.gson.stream.MalformedJsonException;

/**
 * A JSON value together with its path in the document ({@code spheres[1].radius}; the root's path
 * is empty) and the name of the file it came from, so every check can fail with a one-line
 * {@link ModelFormatException} {@code file: path: expected …, found …}. Input echoed in a message
 * (keys, strings, numbers) is cut to 60 characters ({@link Echo}).
 *
 * <p>{@link #parse} reads strict RFC 8259 JSON with Gson's {@link JsonReader} (no comments, no
 * NaN/Infinity, no trailing commas, no duplicate keys) and reports syntax errors with the line
 * and column Gson gives. Numbers keep their literal text ({@link NumberLiteral}), so {@code -0.0}
 * survives and out-of-range literals such as {@code 1e400} are caught by {@link #asDouble()}.
 */
final class JsonNode {

    /** Deepest nesting accepted; a scene file needs about six levels. */
    static final int MAX_NESTING = 64;

    private static final Pattern GSON_POSITION =
            Pattern.compile("(?s)(.*?) at line (\\d+) column (\\d+) path (\\S*).*");
    private static final Pattern IDENTIFIER = Pattern.compile("[A-Za-z_][A-Za-z0-9_-]*");

    private final JsonElement value;
    private final String path;
    private final String fileName;

    private JsonNode(JsonElement value, String path, String fileName) {
        this.value = value;
        this.path = path;
        this.fileName = fileName;
    }

    /** Parses a whole document (the root at path {@code $}). */
    static JsonNode parse(String json, String fileName) {
        try (JsonReader in = new JsonReader(new StringReader(json))) {
            in.setStrictness(Strictness.STRICT);
            JsonElement root = read(in, "", fileName, 0);
            if (in.peek() != JsonToken.END_DOCUMENT) {
                throw new ModelFormatException(fileName, "unexpected text after the end of the document");
            }
            return new JsonNode(root, "", fileName);
        } catch (MalformedJsonException | EOFException e) {
            throw syntaxError(fileName, e);
        } catch (IOException e) {
            throw new ModelFormatException(fileName, "cannot read: " + IoReasons.of(e));
        }
    }

    private static JsonElement read(JsonReader in, String path, String fileName, int depth) throws IOException {
        if (depth > MAX_NESTING) {
            throw new ModelFormatException(fileName, prefix(path) + "nested more than " + MAX_NESTING
                    + " levels deep");
        }
        switch (in.peek()) {
            case BEGIN_OBJECT -> {
                JsonObject object = new JsonObject();
                in.beginObject();
                while (in.hasNext()) {
                    String key = in.nextName();
                    if (object.has(key)) {
                        throw new ModelFormatException(fileName, prefix(path) + "duplicate key " + Echo.quote(key));
                    }
                    object.add(key, read(in, child(path, key), fileName, depth + 1));
                }
                in.endObject();
                return object;
            }
            case BEGIN_ARRAY -> {
                JsonArray array = new JsonArray();
                in.beginArray();
                while (in.hasNext()) {
                    array.add(read(in, path + "[" + array.size() + "]", fileName, depth + 1));
                }
                in.endArray();
                return array;
            }
            case STRING -> { return new JsonPrimitive(in.nextString()); }
            case NUMBER -> { return new JsonPrimitive(new NumberLiteral(in.nextString())); }
            case BOOLEAN -> { return new JsonPrimitive(in.nextBoolean()); }
            case NULL -> {
                in.nextNull();
                return JsonNull.INSTANCE;
            }
            default -> throw new ModelFormatException(fileName, prefix(path) + "invalid JSON: the document ends"
                    + " where a value was expected");
        }
    }

    /** Turns Gson's two-line message into {@code file:LINE: invalid JSON at column C: what (in path)}. */
    private static ModelFormatException syntaxError(String fileName, IOException e) {
        String message = e.getMessage() == null ? "the text ends too early" : e.getMessage();
        Matcher m = GSON_POSITION.matcher(message);
        if (!m.matches()) {
            return new ModelFormatException(fileName, "invalid JSON: " + Echo.cut(message));
        }
        String what = m.group(1).startsWith("Use JsonReader.setStrictness")
                ? "not strict JSON (comments, single quotes, unquoted words such as NaN or Infinity, trailing"
                        + " commas and text after the end are not allowed)"
                : m.group(1);
        String where = m.group(4).replaceFirst("^\\$\\.?", "");
        return new ModelFormatException(fileName, Integer.parseInt(m.group(2)), "invalid JSON at column "
                + m.group(3) + ": " + what.strip() + (where.isEmpty() ? "" : " (in " + Echo.cut(where) + ")"));
    }

    /** Path of member {@code key} of the object at {@code path}: {@code a.b}, or {@code a["odd key"]}. */
    static String child(String path, String key) {
        if (IDENTIFIER.matcher(key).matches()) {
            return path.isEmpty() ? key : path + "." + key;
        }
        return path + "[" + Echo.quote(key) + "]";
    }

    /** {@code "path: "}, or nothing for the root. */
    private static String prefix(String path) {
        return path.isEmpty() ? "" : path + ": ";
    }

    String path() { return path; }

    /** Short text of this value for messages, as {@link #describe}. */
    String text() { return describe(value); }

    /** An error about this value: {@code file: path: detail} ({@code file: detail} at the root). */
    ModelFormatException error(String detail) {
        return new ModelFormatException(fileName, prefix(path) + detail);
    }

    /** An error {@code file: path: expected …, found …}. */
    ModelFormatException expected(String what) {
        return error("expected " + what + ", found " + describe(value));
    }

    // Objects

    /** Checks that this is an object whose keys are all among {@code allowed}. */
    JsonNode object(String... allowed) {
        if (!value.isJsonObject()) {
            throw expected("an object");
        }
        Set<String> known = Set.of(allowed);
        for (String key : value.getAsJsonObject().keySet()) {
            if (!known.contains(key)) {
                throw error("unknown key " + Echo.quote(key) + " (expected one of: " + list(known) + ")");
            }
        }
        return this;
    }

    /** Keys of an object in file order (after {@link #object} or for a free-form map). */
    List<String> keys() {
        if (!value.isJsonObject()) {
            throw expected("an object");
        }
        return new ArrayList<>(value.getAsJsonObject().keySet());
    }

    boolean has(String key) { return value.getAsJsonObject().has(key); }

    /** Member {@code key}, or null when the key is absent. */
    JsonNode get(String key) {
        JsonElement e = value.getAsJsonObject().get(key);
        return e == null ? null : new JsonNode(e, child(path, key), fileName);
    }

    /** Member {@code key}; an error naming the key when it is absent. */
    JsonNode require(String key) {
        JsonNode n = get(key);
        if (n == null) {
            throw error("missing key \"" + key + "\"");
        }
        return n;
    }

    // Values

    List<JsonNode> array() {
        if (!value.isJsonArray()) {
            throw expected("an array");
        }
        JsonArray a = value.getAsJsonArray();
        List<JsonNode> out = new ArrayList<>(a.size());
        for (int i = 0; i < a.size(); i++) {
            out.add(new JsonNode(a.get(i), path + "[" + i + "]", fileName));
        }
        return out;
    }

    boolean isNumber() { return value.isJsonPrimitive() && value.getAsJsonPrimitive().isNumber(); }

    boolean isObject() { return value.isJsonObject(); }

    boolean isString() { return value.isJsonPrimitive() && value.getAsJsonPrimitive().isString(); }

    /** A finite number. */
    double asDouble() {
        if (!isNumber()) {
            throw expected("a number");
        }
        double d = value.getAsDouble();
        if (!Double.isFinite(d)) {
            throw expected("a finite number");
        }
        return d;
    }

    double asPositive() {
        double d = isNumber() ? value.getAsDouble() : Double.NaN;
        if (!(d > 0) || !Double.isFinite(d)) {
            throw expected("a positive number");
        }
        return d;
    }

    /** A whole number in the {@code int} range. */
    int asInt() {
        if (!isNumber()) {
            throw expected("a whole number");
        }
        BigDecimal d;
        try {
            d = new BigDecimal(value.getAsNumber().toString());
        } catch (NumberFormatException e) {
            throw expected("a whole number");
        }
        if (d.signum() != 0 && d.stripTrailingZeros().scale() > 0) {
            throw expected("a whole number");
        }
        try {
            return d.intValueExact();
        } catch (ArithmeticException e) {
            throw expected("a whole number from " + Integer.MIN_VALUE + " to " + Integer.MAX_VALUE);
        }
    }

    boolean asBoolean() {
        if (!value.isJsonPrimitive() || !value.getAsJsonPrimitive().isBoolean()) {
            throw expected("true or false");
        }
        return value.getAsBoolean();
    }

    String asString() {
        if (!isString()) {
            throw expected("a string");
        }
        return value.getAsString();
    }

    /** An array of exactly {@code count} finite numbers; a bad item is named by its own path. */
    double[] asNumbers(int count) {
        if (!value.isJsonArray() || value.getAsJsonArray().size() != count) {
            throw expected("an array of " + count + " numbers");
        }
        double[] out = new double[count];
        List<JsonNode> items = array();
        for (int i = 0; i < count; i++) {
            out[i] = items.get(i).asDouble();
        }
        return out;
    }

    /** A colour: three finite numbers ≥ 0. */
    double[] asColor() {
        double[] c = asNumbers(3);
        if (!(c[0] >= 0 && c[1] >= 0 && c[2] >= 0)) {
            throw expected("a colour of 3 numbers >= 0");
        }
        return c;
    }

    /**
     * Short text of a value for messages: {@code -2}, {@code "abc"}, {@code an object}; JSON's
     * {@code null} is {@code no value}.
     */
    static String describe(JsonElement e) {
        if (e.isJsonNull()) {
            return "no value";
        }
        if (e.isJsonObject()) {
            return "an object";
        }
        if (e.isJsonArray()) {
            return "an array of " + e.getAsJsonArray().size() + (e.getAsJsonArray().size() == 1 ? " item" : " items");
        }
        JsonPrimitive p = e.getAsJsonPrimitive();
        return p.isString() ? Echo.quote(p.getAsString()) : Echo.cut(p.isNumber() ? p.getAsNumber().toString()
                : p.toString());
    }

    /** For messages: {@code a, b, c} sorted. */
    static String list(Iterable<String> names) {
        TreeSet<String> sorted = new TreeSet<>();
        names.forEach(sorted::add);
        return String.join(", ", sorted);
    }

    /**
     * A JSON number kept as its literal text (a syntactically valid JSON number): {@link #toString()}
     * gives the text back, {@link #doubleValue()} parses it exactly as {@link Double#parseDouble}.
     */
    static final class NumberLiteral extends Number {
        private static final long serialVersionUID = 1L;
        private final String text;

        NumberLiteral(String text) { this.text = text; }

        @Override public double doubleValue() { return Double.parseDouble(text); }

        @Override public float floatValue() { return (float) doubleValue(); }

        @Override public long longValue() { return new BigDecimal(text).longValue(); }

        @Override public int intValue() { return new BigDecimal(text).intValue(); }

        @Override public String toString() { return text; }
    }
}
