"""See tests/ui/window-keys-test: the window under Xvfb, driven by xdotool."""
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from window_driver import Window, changed_fraction  # noqa: E402

coilsim, out, root = sys.argv[1], sys.argv[2], sys.argv[3]
display = os.environ["DISPLAY"]
case = f"{root}/scenes/cases/sphere-7mm-wide-neck.json"
failures = []

# What must stay on screen whatever the window's size: the device controls
# and play / reset.
DEVICE = ["play", "reset", "deployed", "push_speed", "push", "pull", "stop", "twist_rate", "twist_minus",
          "twist_plus", "retract_speed", "retract", "detach"]


def check(ok, what):
    print(("  ok    " if ok else "  FAIL  ") + what)
    if not ok:
        failures.append(what)


def inside(r, box):
    return r[0] >= box[0] - 0.5 and r[1] >= box[1] - 0.5 and r[2] <= box[2] + 0.5 and r[3] <= box[3] + 0.5


def overlap(a, b):
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


def fits(layout, label):
    w, h = layout["window"]
    items = layout["items"]
    panel = items.get("panel")
    check(panel is not None and inside(panel, [0, 0, w, h]), f"{label}: the panel {panel} lies in the {w:g}x{h:g} window")
    for name in DEVICE:
        r = items.get(name)
        check(r is not None and panel is not None and inside(r, panel) and inside(r, [0, 0, w, h]),
              f"{label}: {name} {r} is inside the panel and the window")


def run_window(size):
    dump = f"{out}/layout-run-{size}.json"
    win = Window([coilsim, "run", f"{root}/scenes/default.json", "--size", size], display, dump, out)
    try:
        first = win.wait("the run window's first frames", lambda l: "detach" in l["items"])
        fits(first, f"run window {size}")
        win.key("Escape")
        code, _, err = win.close()
        check(code == 0, f"run window {size}: Esc closes it (exit {code}) {err.strip()[-200:]}")
        return first["sections"]
    finally:
        win.kill()


def offscreen_sections(size):
    """The panel sections of the headless run's picture (its own layout dump)."""
    dump = f"{out}/layout-headless-{size}.json"
    env = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "WAYLAND_DISPLAY")}
    env["COILSIM_LAYOUT_DUMP"] = dump
    r = subprocess.run([coilsim, "run", f"{root}/scenes/default.json", "--headless", "--duration", "0.01",
                        "--size", size, "--screenshot", f"{out}/headless-{size}.png"], env=env, cwd=out,
                       capture_output=True, text=True, timeout=120)
    check(r.returncode == 0, f"headless run with a screenshot (exit {r.returncode}) {r.stderr.strip()[-200:]}")
    return json.load(open(dump))["sections"] if os.path.exists(dump) else None


def practice_window_size():
    """practice --window --size 1920x1080 opens at that size, and the panel fits."""
    dump = f"{out}/layout-practice-size.json"
    win = Window([coilsim, "practice", case, "--window", "--coil", "finishing-2x10", "--size", "1920x1080"], display,
                 dump, out)
    try:
        first = win.wait("the practice window's first frames", lambda l: "detach" in l["items"])
        check(first["window"] == [1920, 1080], f"practice --size 1920x1080 opens a {first['window']} window")
        fits(first, "practice window 1920x1080")
        win.key("Escape")
        code, _, err = win.close()
        check(code == 0, f"practice window 1920x1080: Esc closes it (exit {code}) {err.strip()[-200:]}")
    finally:
        win.kill()


def practice_refusal_and_help():
    """The coil is inside: D is refused without asking; F1 shows the help."""
    dump = f"{out}/layout-practice-a.json"
    score = f"{out}/score-a.json"
    win = Window([coilsim, "practice", case, "--window", "--coil", "finishing-2x10", "--out", score], display, dump, out)
    try:
        first = win.wait("the practice window's first frames", lambda l: "detach" in l["items"])
        fits(first, "practice window 1280x720")
        win.key("d")
        win.frames(4)
        l = win.layout()
        check(not l["detach_confirm_open"] and "not fully out" in l["last_message"],
              f"D with the coil inside is refused at once, no confirmation ({l['last_message']!r})")
        for old in ("coilsim-1.png", "coilsim-2.png"):
            if os.path.exists(f"{out}/{old}"):
                os.remove(f"{out}/{old}")
        win.key("F12")
        win.frames(4)
        win.key("F1")
        win.wait("the help overlay", lambda l: l["help_open"] and "help_overlay" in l["items"])
        win.frames(3)  # ImGui places an auto-sized window from its second frame on
        shown = win.layout()
        win.key("F12")
        win.frames(4)
        rect = shown["items"]["help_overlay"]
        check(rect[0] >= shown["items"]["panel"][2] - 0.5, f"the help overlay {rect} lies right of the panel")
        ok = os.path.exists(f"{out}/coilsim-1.png") and os.path.exists(f"{out}/coilsim-2.png")
        frac = changed_fraction(f"{out}/coilsim-1.png", f"{out}/coilsim-2.png", rect) if ok else 0.0
        check(frac > 0.2, f"F1: {100 * frac:.0f} % of the overlay's rectangle changed in the screenshot (need 20 %)")
        win.key("Escape")
        l = win.wait("the help to close", lambda l: not l["help_open"])
        check(win.proc.poll() is None, "Esc closes the help first, not the window")
        win.key("Escape")
        code, _, err = win.close()
        sheet = json.load(open(score))
        check(not sheet["detached"], f"the score sheet says not detached (exit {code})")
    finally:
        win.kill()


def practice_detach():
    """The coil pushed out by a script: cancel by Esc and by mouse, then D, Enter detaches."""
    dump = f"{out}/layout-practice-b.json"
    score = f"{out}/score-b.json"
    script = f"{out}/push-out.json"
    json.dump({"format": "coilsim-timeline/1", "name": "push-out",
               "commands": [{"t_s": 0.0, "push": {"speed_mm_s": 8}}]}, open(script, "w"))
    win = Window([coilsim, "practice", case, "--window", "--coil", "finishing-2x10", "--input", script,
                  "--out", score], display, dump, out)
    try:
        win.wait("the coil fully out", lambda l: l["deployed_mm"] >= l["coil_mm"] - 1e-6 and l["coil_mm"] > 0, 120)
        win.key("d")
        win.wait("the confirmation", lambda l: l["detach_confirm_open"] and "detach_confirm" in l["items"])
        win.frames(3)  # placed from its second frame on
        asked = win.layout()
        confirm, reset = asked["items"]["detach_confirm"], asked["items"]["reset"]
        check(confirm[0] >= asked["items"]["panel"][2] and not overlap(confirm, reset),
              f"the confirmation's button {confirm} is over the scene, not over Reset {reset}")
        win.key("Escape")
        l = win.wait("Esc to cancel", lambda l: not l["detach_confirm_open"])
        win.frames(5)
        l = win.layout()
        check(not l["detached"] and win.proc.poll() is None, "D then Esc cancels: not detached, the window open")
        win.click(l["items"]["detach"])
        asked = win.wait("the confirmation by mouse", lambda l: l["detach_confirm_open"] and "detach_cancel" in l["items"])
        win.frames(3)
        win.click(win.layout()["items"]["detach_cancel"])
        win.wait("the Cancel button", lambda l: not l["detach_confirm_open"])
        win.frames(5)
        check(not win.layout()["detached"], "the Detach button then Cancel by mouse: not detached")
        win.key("d")
        win.wait("the confirmation again", lambda l: l["detach_confirm_open"])
        win.key("Return")
        l = win.wait("the detach", lambda l: l["detached"])
        check(not l["detach_confirm_open"], "D then Enter detaches and closes the confirmation")
        win.key("Escape")
        code, _, err = win.close()
        sheet = json.load(open(score))
        check(sheet["detached"], f"the score sheet says detached (exit {code})")
    finally:
        win.kill()


# What must stay on screen in the validate window: the stage table (to its
# last column), the effect toggles, Fit with its progress, the before switch.
VALIDATE = ["stages", "stages_last_column", "effects", "fit", "progress", "show_before"]


def validate_window(size, fit):
    """The validate window at `size` (None: its default, which must be 1280x720)
    fits, before and (with `fit`) after a fit; F1 shows the help beside the
    panel; Esc hides it, a second Esc closes the window."""
    label = f"validate window {size or 'default'}{' after a fit' if fit else ''}"
    dump = f"{out}/layout-validate-{size or 'default'}{'-fit' if fit else ''}.json"
    example = f"{root}/examples/measurements/soft-catheter-helix.json"
    argv = [coilsim, "validate", example, "--window", "--quiet"] + (["--size", size] if size else [])
    if fit:
        argv += ["--toggle", "catheter_compliance", "--auto-fit", "--spacing", "4"]
    win = Window(argv, display, dump, out, title="coilsim validate")
    try:
        l = win.wait("the validate window's frames", lambda l: "panel" in l["items"] and (not fit or l["fits"] >= 1
                                                                                         and not l["fitting"]), 120)
        win.frames(3)  # a table and the fitted values are laid out from their second frame on
        l = win.layout()
        w, h = l["window"]
        want = [int(v) for v in (size or "1280x720").split("x")]
        check([w, h] == want, f"{label}: the window is {w:g}x{h:g}, expected {want[0]}x{want[1]}")
        panel = l["items"]["panel"]
        check(inside(panel, [0, 0, w, h]), f"{label}: the panel {panel} lies in the window")
        for name in VALIDATE:
            r = l["items"].get(name)
            check(r is not None and inside(r, panel) and inside(r, [0, 0, w, h]),
                  f"{label}: {name} {r} is inside the panel and the window")
        check(l["stages_clipped_headers"] == 0, f"{label}: {l['stages_clipped_headers']:g} of the table's headers are cut")
        check(w - panel[2] >= 0.4 * w, f"{label}: the 3D view keeps {w - panel[2]:g} of {w:g} pixels")
        win.key("F1")
        shown = win.wait("the help overlay", lambda l: l["help_open"] and "help_overlay" in l["items"])
        win.frames(3)
        shown = win.layout()
        rect = shown["items"]["help_overlay"]
        check(rect[0] >= panel[2] - 0.5 and inside(rect, [0, 0, w, h]),
              f"{label}: the help overlay {rect} lies right of the panel, in the window")
        win.key("Escape")
        win.wait("the help to close", lambda l: not l["help_open"])
        check(win.proc.poll() is None, f"{label}: Esc closes the help first")
        win.key("Escape")
        code, _, err = win.close(timeout=60)
        check(code == 0, f"{label}: Esc closes the validate window (exit {code}) {err.strip()[-200:]}")
    finally:
        win.kill()


for size in ("1280x720", "1920x1080"):
    window = run_window(size)
    picture = offscreen_sections(size)
    check(window == picture and "read-outs" in (window or ""),
          f"{size}: the off-screen picture's panel sections {picture!r} are the window's {window!r}")
practice_window_size()
practice_refusal_and_help()
practice_detach()
validate_window(None, False)
validate_window(None, True)
validate_window("1920x1080", False)
if failures:
    print(f"window-keys-test: FAIL: {len(failures)} check(s):\n  " + "\n  ".join(failures), file=sys.stderr)
    sys.exit(1)
print("window-keys-test: OK")
