package org.beziertracer.ui;

import java.awt.datatransfer.DataFlavor;
import java.awt.datatransfer.UnsupportedFlavorException;
import java.io.File;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;

import javax.swing.TransferHandler;

import org.beziertracer.model.io.FilePaths;
import org.beziertracer.app.FileCommands;

/**
 * Files dropped on the window: a file list goes to {@link FileCommands#openDropped}, which opens
 * the first one the format registry can read (.bpt, .obj, .json) after the unsaved-edits
 * question, or says what can be dropped.
 */
final class FileDrop extends TransferHandler {

    private final FileCommands files;

    FileDrop(FileCommands files) {
        this.files = files;
    }

    @Override
    public boolean canImport(TransferSupport support) {
        return support.isDataFlavorSupported(DataFlavor.javaFileListFlavor);
    }

    @Override
    public boolean importData(TransferSupport support) {
        if (!canImport(support)) {
            return false;
        }
        try {
            List<?> dropped = (List<?>) support.getTransferable().getTransferData(DataFlavor.javaFileListFlavor);
            List<Path> paths = dropped.stream().filter(File.class::isInstance).flatMap(f -> FilePaths.find(((File) f).getPath()).stream()).toList();
            // After the drop completes: the unsaved-edits question must not block the drag source
            javax.swing.SwingUtilities.invokeLater(() -> files.openDropped(paths));
            return !paths.isEmpty();
        } catch (UnsupportedFlavorException | IOException e) {
            return false;
        }
    }
}
