"""The one guard of every file a script writes, as dem/output/output_guard.hpp is the program's.

Before any work, a script names what it will write (`guard`): an output that would destroy what a user
has is refused (`Refused`, exit 2 through scripts/icedem_tool.py) naming the option, the file and why.
Refused: an empty name; an input of the command or another of its outputs (one file under two names
included); a directory where a file goes, a file where a directory goes; an HDF5 file (a run's output
or checkpoint: the scripts write text, CSV, Markdown and pictures); a place that cannot be made or
written (its directories are made on the way). A write that fails afterwards (a full disk) is `WriteFailed`, exit 5;
`write_text` and `save_figure` write through a temporary file renamed into place, so a failed write
leaves the earlier file whole.
"""
import os
import tempfile

FILE, DIRECTORY, VIEWS = "file", "directory", "views"  # VIEWS: an HDF5 file made from a run (its ParaView
# views): it may replace an earlier one, never a run's output or checkpoint (those have /meta)
HDF5_SIGNATURE = b"\x89HDF\r\n\x1a\n"


class Refused(Exception):
    """An output the script must not write (exit 2)."""


class WriteFailed(Exception):
    """An output the script could not write in full (exit 5)."""


def _same(a, b):
    """Whether two paths name one file: the same path once resolved, or one file under two names."""
    if os.path.realpath(a) == os.path.realpath(b):
        return True
    try:
        return os.path.samefile(a, b)
    except OSError:
        return False


def _is_hdf5(path):
    # HDF5 looks for its signature at 0, 512, 1024, 2048, ... (a user block before it)
    try:
        with open(path, "rb") as f:
            for at in (0, 512, 1024, 2048, 4096):
                f.seek(at)
                if f.read(8) == HDF5_SIGNATURE:
                    return True
    except OSError:
        return False
    return False


def _is_run_file(path):
    """Whether an HDF5 file is a run's output or checkpoint (it has /meta); one it cannot read counts."""
    try:
        import h5py  # Debian's python3-h5py
        with h5py.File(path, "r") as f:
            return "meta" in f
    except Exception:  # noqa: BLE001 (unreadable: treated as precious)
        return True


def _writable_parent(path):
    """Why the directory `path` goes in cannot take it ("" if it can): it, or the nearest of its parents
    that exists (the directories between are made on the way), must be a writable directory."""
    parent = os.path.dirname(os.path.abspath(path)) or "."
    while not os.path.exists(parent):
        parent = os.path.dirname(parent)
    if not os.path.isdir(parent):
        return f"{parent} is not a directory"
    if not os.access(parent, os.W_OK | os.X_OK):
        return f"its directory {parent} cannot be written"
    return ""


def guard(outputs, inputs=()):
    """Refuse the outputs that would destroy what a user has, before any work.

    outputs: (option, path, kind) for each file (FILE) or directory (DIRECTORY) the script writes;
    a path of None is an output not asked for. inputs: the files the script reads."""
    named = [(o, p, k) for o, p, k in outputs if p is not None]
    for i, (option, path, kind) in enumerate(named):
        if path == "":
            raise Refused(f"{option} '': give a name")
        for source in inputs:
            if source and _same(path, source):
                raise Refused(f"{option} {path}: it is an input of this command ({source}); it would be overwritten")
        for other_option, other, other_kind in named[:i]:
            if _same(other, path) and not (kind == other_kind == DIRECTORY):  # one directory may take both
                raise Refused(f"{option} {path}: {other_option} writes the same file")
        if kind == DIRECTORY:
            if os.path.exists(path) and not os.path.isdir(path):
                raise Refused(f"{option} {path}: a file, where a directory goes")
            if os.path.isdir(path):
                if not os.access(path, os.W_OK | os.X_OK):
                    raise Refused(f"{option} {path}: the directory cannot be written")
                continue
            why = _writable_parent(path)  # made on the way
            if why:
                raise Refused(f"{option} {path}: cannot be made: {why}")
            continue
        if os.path.isdir(path):
            raise Refused(f"{option} {path}: a directory, where a file goes")
        if os.path.exists(path) and not os.path.isfile(path):
            raise Refused(f"{option} {path}: not a regular file")
        if kind == VIEWS and os.path.isfile(path) and _is_hdf5(path) and not _is_run_file(path):
            pass  # an earlier view of the run: replaced
        elif os.path.isfile(path) and _is_hdf5(path):
            raise Refused(f"{option} {path}: an HDF5 file (a run's output or checkpoint, or its data); this command "
                          f"would destroy it")
        why = _writable_parent(path)
        if why:
            raise Refused(f"{option} {path}: {why}")


def _replace(path, write):
    """`write(f)` writes the whole file to an open binary file, made whole and synced through a
    temporary file beside `path` (write_with)."""
    def write_to(tmp):
        with open(tmp, "wb") as f:
            write(f)
            f.flush()
            os.fsync(f.fileno())
    write_with(path, write_to)


def write_with(path, write_to):
    """`write_to(name)` writes the whole file itself (a writer that takes a file name, such as a
    movie's): it writes a temporary file beside `path`, with the same extension, renamed over
    `path` once whole; raise WriteFailed (exit 5) and leave an earlier file as it was."""
    directory = os.path.dirname(os.path.abspath(path))
    try:
        os.makedirs(directory, exist_ok=True)
    except OSError as e:
        raise WriteFailed(f"cannot make {directory}: {e.strerror or e}") from e
    fd, tmp = tempfile.mkstemp(prefix="." + os.path.basename(path) + ".",
                               suffix=".tmp" + os.path.splitext(path)[1], dir=directory)
    os.close(fd)
    try:
        umask = os.umask(0)
        os.umask(umask)
        mode = os.stat(path).st_mode & 0o777 if os.path.isfile(path) else 0o666 & ~umask
        write_to(tmp)
        os.chmod(tmp, mode)
        os.replace(tmp, path)
    except OSError as e:
        raise WriteFailed(f"cannot write {path}: {e.strerror or e}") from e
    finally:
        if os.path.exists(tmp):
            os.unlink(tmp)


def write_text(path, text):
    """Write `text` to `path` whole, or raise WriteFailed (exit 5) and leave an earlier file as it was."""
    _replace(path, lambda f: f.write(text.encode("utf-8")))


def save_figure(fig, path, **options):
    """A matplotlib figure saved as write_text saves text."""
    fmt = os.path.splitext(path)[1].lstrip(".") or "png"
    _replace(path, lambda f: fig.savefig(f, format=fmt, **options))
