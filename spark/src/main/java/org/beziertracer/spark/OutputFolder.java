package org.beziertracer.spark;

import java.io.IOException;
import java.io.OutputStream;
import java.net.URI;

import org.apache.hadoop.conf.Configuration;
import org.apache.hadoop.fs.FSDataInputStream;
import org.apache.hadoop.fs.FileSystem;
import org.apache.hadoop.fs.LocalFileSystem;
import org.apache.hadoop.fs.Path;
import org.apache.spark.TaskContext;

/**
 * The output folder of a job on any Hadoop file system ({@code file://}, {@code hdfs://}, {@code s3a://}):
 * tiles under {@code tiles/}, frames at the top. Every file is written whole under a temporary name in the
 * same folder and renamed into place, so a reader (a resumed run, the assembly) sees a file whole or not
 * at all; a tile another attempt already renamed into place is kept (its bytes are the same).
 */
final class OutputFolder {
    private final FileSystem fs;
    private final Path root;

    OutputFolder(String uri) throws IOException {
        URI u = URI.create(uri);
        FileSystem f = FileSystem.get(u, new Configuration());
        f.setWriteChecksum(false); // no .NAME.crc beside each file on file:// (other file systems keep their own)
        // file://: Hadoop's LocalFileSystem reads every file through its checksum layer, 512 bytes a call, even
        // without a .crc file; the raw one under it reads a tile in one call
        this.fs = f instanceof LocalFileSystem local ? local.getRaw() : f;
        this.root = new Path(u);
    }

    /** A name for this task attempt's temporary files: stage and attempt ids ({@code local} outside a task). */
    static String attemptTag() {
        TaskContext task = TaskContext.get();
        return task == null ? "local" + ProcessHandle.current().pid() : task.stageId() + "-" + task.taskAttemptId();
    }

    Path tile(String name) { return new Path(new Path(root, "tiles"), name); }

    Path frame(String name) { return new Path(root, name); }

    boolean exists(Path p) throws IOException { return fs.exists(p); }

    /** The bytes of {@code p}, read in one piece (files here are written whole and never change). */
    byte[] read(Path p) throws IOException {
        long length = fs.getFileStatus(p).getLen();
        if (length > Integer.MAX_VALUE - 8) {
            throw new IOException(p + ": " + length + " bytes is too big for a tile or frame file");
        }
        byte[] bytes = new byte[(int) length];
        try (FSDataInputStream in = fs.open(p)) {
            in.readFully(0, bytes);
        }
        return bytes;
    }

    /** The file system the folder is on (for {@code file://}: the raw local one, without checksums). */
    FileSystem fileSystem() { return fs; }

    /**
     * Writes {@code bytes} to {@code target} atomically (temporary name {@code .NAME.TAG.tmp}, then rename);
     * when another attempt got there first, its file (the same bytes) is kept.
     */
    void writeAtomically(Path target, byte[] bytes, String tag) throws IOException {
        Path tmp = new Path(target.getParent(), "." + target.getName() + "." + tag + ".tmp");
        try (OutputStream out = fs.create(tmp, true)) {
            out.write(bytes);
        }
        if (!fs.rename(tmp, target)) {
            fs.delete(tmp, false);
            if (!fs.exists(target)) {
                throw new IOException("cannot rename " + tmp + " to " + target);
            }
        }
    }
}
