import java.io.ByteArrayOutputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Wraps the 256×256 launcher icon {@code beziertracer.png} into the containers jpackage wants on
 * Windows ({@code .ico}) and macOS ({@code .icns}); Linux takes the PNG. The PNG is the teapot,
 * rendered by the app's own command line:
 * <pre>
 * java -jar target/beziertracer.jar render teapot -o src/dist/beziertracer.png --size 256x256 --spp 16 \
 *   --sampler jittered --quiet --eye 160,-300,220 --target 10,0,55 --up 0,0,1 --fov 38 \
 *   --light -200,-350,450 --light 300,-100,300
 * </pre>
 * Both formats may hold a PNG as is: an ICO directory with one 256-pixel entry
 * (width and height written as 0), and an ICNS file with one {@code ic08} (256×256) element.
 * Run from the repository root with the JDK alone: {@code java src/dist/MakeIcons.java}.
 */
public final class MakeIcons {
    public static void main(String[] args) throws IOException {
        Path dir = Path.of("src/dist");
        byte[] png = Files.readAllBytes(dir.resolve("beziertracer.png"));
        Files.write(dir.resolve("beziertracer.ico"), ico(png));
        Files.write(dir.resolve("beziertracer.icns"), icns(png));
    }

    static byte[] ico(byte[] png) throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        DataOutputStream out = new DataOutputStream(bytes);
        out.writeShort(0);                       // reserved
        out.writeShort(Short.reverseBytes((short) 1)); // type 1 = icon (little-endian from here)
        out.writeShort(Short.reverseBytes((short) 1)); // one image
        out.writeByte(0);                        // width 256
        out.writeByte(0);                        // height 256
        out.writeByte(0);                        // no palette
        out.writeByte(0);                        // reserved
        out.writeShort(Short.reverseBytes((short) 1));  // colour planes
        out.writeShort(Short.reverseBytes((short) 32)); // bits per pixel
        out.writeInt(Integer.reverseBytes(png.length));
        out.writeInt(Integer.reverseBytes(6 + 16));     // the PNG follows the one directory entry
        out.write(png);
        return bytes.toByteArray();
    }

    static byte[] icns(byte[] png) throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        DataOutputStream out = new DataOutputStream(bytes);
        out.writeBytes("icns");
        out.writeInt(8 + 8 + png.length);        // whole file, big-endian
        out.writeBytes("ic08");                  // 256×256 PNG
        out.writeInt(8 + png.length);
        out.write(png);
        return bytes.toByteArray();
    }
}
