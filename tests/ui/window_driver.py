"""Drives coilsim's real window under Xvfb with xdotool (keys, mouse) and
reads back what the window says about itself: the layout dump it writes
every frame when COILSIM_LAYOUT_DUMP is set (each control's rectangle, the
confirmation and help state, the coil's deployed length) and its F12
screenshots. Used by tests/ui/window-keys-test."""
import json
import os
import struct
import subprocess
import time
import zlib


class Window:
    """One coilsim window process on an X display, with its layout dump."""

    def __init__(self, argv, display, dump, cwd, env=None, title="coilsim"):
        self.dump = dump
        if os.path.exists(dump):
            os.remove(dump)
        e = dict(os.environ if env is None else env)
        e["DISPLAY"] = display
        e["COILSIM_LAYOUT_DUMP"] = dump
        self.env = e
        # Files, not pipes: a window that prints much must never block on a full pipe.
        base = os.path.splitext(dump)[0]
        self.out_path, self.err_path = base + ".stdout", base + ".stderr"
        self.proc = subprocess.Popen(argv, cwd=cwd, env=e, stdout=open(self.out_path, "w"),
                                     stderr=open(self.err_path, "w"))
        self.id = self.xdo("search", "--sync", "--onlyvisible", "--name", title).split()[0]
        self.xdo("windowfocus", "--sync", self.id)

    def xdo(self, *args):
        r = subprocess.run(["xdotool", *args], env=self.env, capture_output=True, text=True, timeout=60)
        if r.returncode != 0:
            raise RuntimeError(f"xdotool {' '.join(args)}: {r.stderr.strip()}")
        return r.stdout

    def key(self, *keys):
        self.xdo("key", "--clearmodifiers", *keys)

    def click(self, rect):
        """Moves onto the middle of `rect` (window units), lets ImGui see the hover, clicks."""
        x, y = int((rect[0] + rect[2]) / 2), int((rect[1] + rect[3]) / 2)
        self.xdo("mousemove", "--window", self.id, str(x), str(y))
        self.frames(3)
        self.xdo("click", "1")

    def layout(self):
        with open(self.dump) as f:
            return json.load(f)

    def wait(self, what, predicate, timeout=60.0):
        """The first layout dump for which predicate(dump) holds; fails after `timeout` s."""
        end, last = time.time() + timeout, None
        while time.time() < end:
            if self.proc.poll() is not None:
                raise AssertionError(f"the window closed while waiting for {what}: {open(self.err_path).read()}")
            try:
                last = self.layout()
                if predicate(last):
                    return last
            except (OSError, ValueError):
                pass  # not written yet
            time.sleep(0.05)
        raise AssertionError(f"timed out waiting for {what}; last layout: {last}")

    def frames(self, n):
        """Waits until the window has drawn `n` more frames (each rewrites the dump)."""
        for _ in range(n):
            try:
                before = os.stat(self.dump).st_mtime_ns
            except OSError:
                before = 0
            end = time.time() + 30
            while time.time() < end:
                try:
                    if os.stat(self.dump).st_mtime_ns != before:
                        break
                except OSError:
                    pass
                time.sleep(0.01)

    def close(self, timeout=60):
        """Waits for the process to end; returns (exit code, stdout, stderr)."""
        self.proc.wait(timeout=timeout)
        return self.proc.returncode, open(self.out_path).read(), open(self.err_path).read()

    def kill(self):
        if self.proc.poll() is None:
            self.proc.kill()
            self.proc.wait()


def read_png(path):
    """(width, height, bytes per pixel, rows) of an 8-bit RGB(A) non-interlaced PNG."""
    d = open(path, "rb").read()
    i, idat = 8, b""
    while i < len(d):
        n, t = struct.unpack(">I4s", d[i:i + 8])
        b = d[i + 8:i + 8 + n]
        i += 12 + n
        if t == b"IHDR":
            w, h, depth, ctype, _, _, lace = struct.unpack(">IIBBBBB", b)
            assert depth == 8 and lace == 0 and ctype in (2, 6), path
        elif t == b"IDAT":
            idat += b
    bpp = 3 if ctype == 2 else 4
    raw, stride, rows, prev, p = zlib.decompress(idat), w * bpp, [], bytearray(w * bpp), 0
    for _ in range(h):
        f, line = raw[p], bytearray(raw[p + 1:p + 1 + stride])
        p += 1 + stride
        for x in range(stride):
            a = line[x - bpp] if x >= bpp else 0
            b, c = prev[x], (prev[x - bpp] if x >= bpp else 0)
            if f == 1:
                line[x] = (line[x] + a) & 255
            elif f == 2:
                line[x] = (line[x] + b) & 255
            elif f == 3:
                line[x] = (line[x] + ((a + b) >> 1)) & 255
            elif f == 4:
                q = a + b - c
                pa, pb, pc = abs(q - a), abs(q - b), abs(q - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    return w, h, bpp, rows


def changed_fraction(a, b, rect, levels=40):
    """Share of the pixels inside rect = [x0, y0, x1, y1] (top-left origin)
    that differ by more than `levels` in a colour channel between two PNGs."""
    (w, h, ba, ra), (w2, h2, bb, rb) = read_png(a), read_png(b)
    assert (w, h) == (w2, h2), (a, b)
    x0, y0 = max(0, int(rect[0])), max(0, int(rect[1]))
    x1, y1 = min(w, int(rect[2])), min(h, int(rect[3]))
    n = changed = 0
    for y in range(y0, y1):
        for x in range(x0, x1):
            n += 1
            if max(abs(ra[y][x * ba + k] - rb[y][x * bb + k]) for k in range(3)) > levels:
                changed += 1
    return changed / max(n, 1)
