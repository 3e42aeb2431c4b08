// The table of commands and options (see commands.h): the only place their
// names, values, bounds and help are written.
#include "app/commands.h"

#include <array>

namespace coilsim::app {
namespace {

using K = ValueKind;
using sv = std::string_view;

// One constructor per kind of option, so each line says what it is.
constexpr OptionSpec flag(sv name, sv help) {
  OptionSpec o;
  o.name = name, o.help = help;
  return o;
}
constexpr OptionSpec value(sv name, ValueKind kind, sv placeholder, sv help) {
  OptionSpec o = flag(name, help);
  o.kind = kind, o.value = placeholder;
  return o;
}
constexpr OptionSpec number(sv name, sv placeholder, sv help, double min, double max, bool openMin = false) {
  OptionSpec o = value(name, K::Number, placeholder, help);
  o.min = min, o.max = max, o.openMin = openMin;
  return o;
}
constexpr OptionSpec integer(sv name, sv placeholder, sv help, double min, double max) {
  OptionSpec o = number(name, placeholder, help, min, max);
  o.kind = K::Integer;
  return o;
}
constexpr OptionSpec choice(sv name, sv placeholder, sv help, sv choices) {
  OptionSpec o = value(name, K::Choice, placeholder, help);
  o.choices = choices;
  return o;
}
constexpr OptionSpec size(sv name, sv placeholder, sv help, double min, double max) {
  OptionSpec o = value(name, K::Size, placeholder, help);
  o.min = min, o.max = max;
  return o;
}

constexpr OptionSpec kQuiet = flag("--quiet", "no progress on stderr (progress shows only on a terminal anyway)");

constexpr std::array kRun{
    flag("--headless", "run off-screen: print a summary, no window"),
    value("--out", K::OutFile, "FILE", "write the final state as JSON (coilsim-result/1, atomically)"),
    value("--input", K::JsonFile, "TIMELINE",
          "drive the scene's coil deployment by timed commands (coilsim-timeline/1: push, pull, twist, stop, "
          "detach, retract; see timelines/*.json)"),
    number("--duration", "S", "simulated seconds, instead of the scene's duration_s (dynamic scenes)", 0, 3600,
           true),
    integer("--steps", "N", "number of time steps instead (dynamic scenes)", 1, double(kMaxRunSteps)),
    value("--screenshot", K::OutFile, "PNG",
          "write a picture of the final state (off-screen), or of the window's last frame"),
    choice("--view", "V", "3d, xray or biplane (default 3d)", "3d|xray|biplane"),
    size("--size", "WxH", "image or window size in pixels (default 1280x720)", 16, 16384),
    kQuiet,
};

constexpr std::array kBench{
    flag("--json", "print the figures as one JSON document"),
    flag("--quick", "fewer repeats: rougher figures in a fraction of the time"),
    flag("--contact", "the contact figures alone (detection against its fresh-query baseline, dense packing)"),
    flag("--practice", "the practice window's figures alone (four coils in the 7 mm sac, a fifth pushed)"),
    kQuiet,
};

constexpr std::array kMesh{
    number("--scale-to-mm", "S", "multiply the file's coordinates by S to get millimetres (1000 for a file in metres)",
           0, kNoBound, true),
};

constexpr std::array kPhantom{
    choice("--type", "T", "the parent vessel", "sidewall|curved|bifurcation"),
    number("--sac-mm", "D", "sac diameter in mm", 1, 40),
    number("--dome-to-neck", "R", "dome-to-neck ratio D/W (default 2)", 1, 10),
    number("--neck-mm", "W", "neck width in mm (instead of --dome-to-neck)", 0.1, 40),
    number("--sac-height-mm", "H", "sac height along the dome axis (default D: a sphere; else an ellipsoid)", 0.5, 120),
    integer("--lobes", "N", "lobes of the sac", 1, 6),
    number("--vessel-mm", "V", "parent vessel diameter in mm (default 4)", 1, 10),
    number("--resolution-mm", "H", "grid spacing in mm (default 0.3)", 0.02, 5),
    value("--out", K::OutFile, "FILE.stl", "writes FILE.stl (binary, mm) and FILE.phantom.json (sac, neck plane)"),
};

constexpr std::array kPlan{
    value("--out", K::Directory, "DIR", "write DIR/plan.json, DIR/plan.md and a picture per coil"),
    value("--coils", K::CoilList, "a,b+c",
          "catalogue coils: a,b two candidates, b+c one sequence into the same sac (default: the case's first "
          "sequence, else each coil of its set)"),
    value("--sequence", K::Text, "NAME", "a case's sequence of coils (its \"sequences\"), deployed into one sac"),
    integer("--jobs", "N", "candidates run on N threads", 1, 256),
    value("--sac", K::JsonFile, "FILE", "the sac and neck plane of a scene ({\"sac\": {...}})"),
    value("--catalogue", K::Directory, "DIR", "a directory of coil files instead of the installed catalogue"),
    number("--speed", "MM_S", "push speed in mm/s", 0, kNoBound, true),
    number("--force-threshold", "MN", "tip force in mN above which the operator pulls back", 0, kNoBound, true),
    number("--spacing", "MM", "beam length in mm", 0, kNoBound, true),
    number("--max-time", "S", "simulated seconds before a coil is given up", 0, kNoBound, true),
    value("--sensitivity", K::Text, "SHIFT_MM,TILT_DEG",
          "also run each coil with the catheter tip shifted and tilted (e.g. 0.5,5)"),
    choice("--sleep", "MODE", "placed coils at rest sleep: on, off or auto (on for sequences); default: as the scene says (off)", "on|off|auto"),
    flag("--no-screenshots", "no pictures"),
    size("--size", "WxH", "picture size in pixels (default 960x720)", 16, 8192),
    kQuiet,
};

constexpr std::array kExperiment{
    value("--cavity-ratio", K::Text, "a,b", "cavity diameter over wire diameter, one run each (default 20)"),
    value("--friction", K::Text, "a,b", "Coulomb friction coefficients, one run each (default 0,0.1,0.3)"),
    number("--packing", "PHI", "stop at this packing fraction (default 0.1)", 0, 0.5, true),
    value("--turns", K::Text, "a,b", "twist turned at the catheter per cavity diameter pushed, one run each (default 0)"),
    integer("--jobs", "N", "runs on N threads", 1, 256),
};

constexpr std::array kPlanMerge{
    value("--out", K::Directory, "DIR", "write the merged DIR/plan.json and DIR/plan.md"),
};

constexpr std::array kPractice{
    value("--coil", K::Coil, "NAME[+NAME...]",
          "a coil of the case's set (default its first); a+b+c: the session's coils, each next one going in once the "
          "one before has detached"),
    value("--input", K::JsonFile, "TIMELINE", "play these timed commands (coilsim-timeline/1)"),
    value("--replay", K::JsonFile, "SESSION", "replay a recorded session (coilsim-session/1)"),
    flag("--window", "practise by hand in the window; recorded and scored when it closes"),
    choice("--view", "V", "3d, xray or biplane (default 3d)", "3d|xray|biplane"),
    value("--views", K::Text, "T:VIEW,...", "switch views at these times, e.g. 0.5:xray,2:3d"),
    number("--duration", "S", "simulated seconds (default: one after the last command)", 0, kNoBound, true),
    value("--record", K::OutFile, "SESSION", "write the session, to replay it"),
    value("--screenshot", K::OutFile, "PNG", "a picture of the last frame with the read-outs"),
    value("--out", K::OutFile, "SCORE", "write the score sheet (JSON)"),
    size("--size", "WxH", "window or picture size in pixels (default 1280x720)", 16, 16384),
    kQuiet,
};

// validate and diagnose share these (app/validate_cmd.h: WorkbenchArgs).
constexpr OptionSpec kWorkbenchOut =
    value("--out", K::Directory, "DIR", "write the report, its tables and plots into DIR");
constexpr OptionSpec kFit =
    value("--fit", K::List, "a,b", "fit these parameters (a rod quantity, e.g. young_modulus_gpa; EFFECT.PARAM; or an effect's name)");
constexpr OptionSpec kSpacing = number("--spacing", "MM", "beam length in mm (default 2)", 0.05, 100);
constexpr OptionSpec kPushIncrement =
    number("--push-increment", "MM", "deployed length between static solves in mm (default 2)", 0.05, 100);
constexpr OptionSpec kNoPlots = flag("--no-plots", "no PNG plots");
constexpr OptionSpec kQuietWorkbench = flag("--quiet", "no progress or phase lines on stderr");

constexpr std::array kValidate{
    value("--effects", K::List, "a,b", "switch these effects on (coilsim help lists them)"),
    kWorkbenchOut,
    kFit,
    kSpacing,
    kPushIncrement,
    kNoPlots,
    kQuietWorkbench,
    flag("--window", "the panel: effect toggles, Fit, live plots, 3D error"),
    value("--screenshot", K::OutFile, "PNG", "the panel off-screen, as a picture"),
    value("--toggle", K::List, "a,b", "effects the panel switches on before the picture"),
    flag("--auto-fit", "the panel presses Fit before the picture"),
    size("--size", "WxH", "window or panel picture size in pixels (default 1280x720)", 16, 16384),
};

constexpr std::array kDiagnose{
    value("--candidates", K::List, "a,b", "the effects to try (default: every effect that has a diagnosis)"),
    kWorkbenchOut,
    kFit,
    kSpacing,
    kPushIncrement,
    kNoPlots,
    kQuietWorkbench,
};

constexpr std::array kCase{
    value("--out", K::OutFile, "CASE.json", "write the case (coilsim-case/1)"),
    value("--sac-point", K::Text, "X,Y,Z", "new: a point inside the sac (mm) when the surface has several"),
    value("--catalogue", K::Directory, "DIR", "new: the catalogue the first coil is chosen from"),
    number("--neck-shift", "MM", "edit: move the neck plane along its normal (mm)", -20, 20),
    value("--neck-through", K::Text, "X,Y,Z", "edit: put the neck plane through this point (mm)"),
    value("--tip", K::Text, "X,Y,Z", "edit: put the catheter tip here (mm)"),
    flag("--window", "edit: in the window (drag the neck plane, click the tip, Ctrl+S saves)"),
    value("--screenshot", K::OutFile, "PNG",
          "edit: the editor's view as a picture (off-screen; with --window its last frame)"),
};

constexpr std::array<OptionSpec, 0> kNone{};

constexpr std::array kCommands{
    CommandSpec{"run", "simulate a scene file (scenes/*.json, docs/scene-format.md)",
                "run SCENE [options]\nSCENE [options]   (the same)", "SCENE", K::JsonFile, 1, 1, kRun,
                "Without --headless, a window opens if there is a display; otherwise the scene\n"
                "runs off-screen as with --headless. A run of more than 100000000 steps is refused\n"
                "before it starts; Ctrl-C (SIGINT) or SIGTERM stops a run after the current step and\n"
                "writes --out of the state reached.\n"
                "exit codes: 0 ok (refused timeline commands are reported, not failures), 1 simulation\n"
                "            failed (step refused, static solve not converged) or rendering failed,\n"
                "            2 bad command line or input file (scene or timeline),\n"
                "            130 / 143 stopped by SIGINT / SIGTERM"},
    CommandSpec{"bench", "time steps and solvers (README, Performance)", "", "", K::None, 0, 0, kBench,
                "Timings come with ratios against baselines measured in the same run; nothing fails on time."},
    CommandSpec{"mesh", "check an aneurysm surface and say what loading would repair", "", "FILE", K::MeshFile, 1, 1,
                kMesh,
                "Reads STL, OBJ, PLY or OFF; warns when the scaled surface is no aneurysm's size.\n"
                "exit codes: 0 usable as a wall, 2 unreadable or unusable"},
    CommandSpec{"phantom", "make an aneurysm phantom (surface and its sac description)",
                "phantom --type T --sac-mm D [--dome-to-neck R | --neck-mm W] [options] --out FILE.stl", "", K::None, 0,
                0, kPhantom, "exit codes: 0 written, 1 the surface came out unusable, 2 bad options"},
    CommandSpec{"plan", "compare catalogue coils in an aneurysm (docs/planning.md)",
                "plan SCENE|CASE... --out DIR [--coils a,b+c] [options]", "SCENE|CASE", K::JsonFile, 1, -1, kPlan,
                "Several case files: one plan each in DIR/<case>/ and every table in DIR/plan.md.\n"
                "Ctrl-C (SIGINT) or SIGTERM: no new candidate starts; those finished are written.\n"
                "exit codes: 0 ok, 1 a candidate's simulation failed, 2 bad input, 130 / 143 stopped"},
    CommandSpec{"plan-merge", "merge plans (e.g. of a Slurm job array)", "", "DIR", K::Directory, 1, -1, kPlanMerge,
                "exit codes: 0 ok, 2 a directory holds no coilsim-plan/1 plan.json"},
    CommandSpec{"experiment", "a published dense-packing experiment: a wire injected into a sphere (docs/planning.md)",
                "experiment injection [--cavity-ratio a,b] [--friction a,b] [--turns a,b] [--packing PHI]\n"
                "           [--jobs N]",
                "injection", K::Text, 1, 1, kExperiment,
                "Prints one Markdown table row per cavity ratio, friction coefficient and torsion.\n"
                "exit codes: 0 ok, 1 a run's step was refused (the others are printed), 2 bad input"},
    CommandSpec{"practice", "play or replay a practice session, write its score sheet (docs/planning.md)",
                "practice CASE --coil NAME --input TIMELINE [--view V] [--views T:VIEW,...] [--duration S]\n"
                "         [--record SESSION] [--screenshot PNG] [--size WxH] --out SCORE\n"
                "practice CASE --replay SESSION [--screenshot PNG] [--size WxH] --out SCORE\n"
                "practice CASE --window [--coil NAME] [--view V] [--record SESSION] [--out SCORE]\n"
                "         [--input TIMELINE] [--views T:VIEW,...] [--duration S] [--screenshot PNG] [--size WxH]",
                "CASE", K::JsonFile, 1, 1, kPractice, "exit codes: 0 ok, 1 a step was refused, 2 bad input"},
    CommandSpec{"validate", "the model against a measured coil (docs/validation.md)",
                "validate FILE... [--effects a,b] [--fit young_modulus_gpa,...] --out DIR [options]   (several: jointly)\n"
                "validate FILE --window [--effects a,b] [--fit ...] [--size WxH]   (the panel)\n"
                "validate FILE --screenshot PNG [--toggle a,b] [--auto-fit] [--size WxH]   (the panel off-screen)",
                "FILE...", K::JsonFile, 1, -1, kValidate,
                "Writes DIR/report.json, DIR/report.md and the plots. Ctrl-C (SIGINT) or SIGTERM stops a\n"
                "fit after the current evaluation and writes the report of the values reached.\n"
                "exit codes: 0 ok, 1 a stage failed or the fit did not finish, 2 bad input, 130 / 143 stopped"},
    CommandSpec{
        "diagnose", "which physical effect is missing (docs/validation.md)",
        "diagnose FILE... --out DIR [options]   (several files of one coil: fitted jointly)", "FILE...", K::JsonFile, 1,
        -1, kDiagnose,
        "Writes DIR/diagnosis.json and DIR/diagnosis.md.\nexit codes: 0 ok, 1 the diagnosis failed, 2 bad input"},
    CommandSpec{"case", "a planning case from a patient's surface, or edit one (docs/planning.md)",
                "case new SURFACE --out CASE.json [--sac-point X,Y,Z] [--catalogue DIR]\n"
                "case edit CASE.json [--neck-shift MM] [--neck-through X,Y,Z] [--tip X,Y,Z] --out NEW.json\n"
                "case edit CASE.json --window [--out NEW.json] [--screenshot PNG]",
                "new|edit FILE", K::Text, 2, 2, kCase,
                "new: finds the sac and neck, the catheter tip, the morphology and a first coil; when unsure\n"
                "(two sacs, no clear neck) it asks for --sac-point instead of guessing.\n"
                "edit --window: the surface, the sac (orange), the neck plane (cyan disc and normal) and the\n"
                "catheter tip; shift + drag up/down moves the neck plane along its normal (0.05 mm a pixel),\n"
                "Up/Down 0.1 mm, Page Up/Down 1 mm, I/K J/L tilt 1 deg, ctrl + click puts it through a surface\n"
                "point; a click on the surface (or a drag from the tip) puts the tip mid-lumen there, T aims\n"
                "it at the neck; the morphology updates live and refusals say why. Ctrl+S saves to --out\n"
                "(without --out over CASE.json, after asking); Esc closes, asking when edits are unsaved.\n"
                "exit codes: 0 written (or the window closed), 1 no display or GL, 2 bad input or a surface\n"
                "            it will not guess on"},
    CommandSpec{"completion", "print the bash completion script (installed with coilsim)", "completion bash", "bash",
                K::Choice, 1, 1, kNone, "Try it without installing: source <(coilsim completion bash)"},
    CommandSpec{"help", "this text, or one command's usage", "help [COMMAND]\nCOMMAND --help\n--version", "COMMAND",
                K::Text, 0, 1, kNone, ""},
};

}  // namespace

std::span<const CommandSpec> commands() { return kCommands; }

const CommandSpec* findCommand(std::string_view name) {
  for (const CommandSpec& c : kCommands)
    if (c.name == name) return &c;
  return nullptr;
}

const OptionSpec* findOption(const CommandSpec& command, std::string_view name) {
  for (const OptionSpec& o : command.options)
    if (o.name == name) return &o;
  return nullptr;
}

}  // namespace coilsim::app
