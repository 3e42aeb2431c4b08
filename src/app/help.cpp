#include "app/help.h"

#include <algorithm>
#include <string_view>

#include "app/options.h"
#include "app/graphics.h"
#include "app/run_scene.h"
#include "physics/effect.h"
#include "physics/rod_quantities.h"
#include "validation/params.h"

namespace coilsim::app {
namespace {

// Options that need the ui layer, noted as such in a build without it.
bool needsUi(const CommandSpec& c, const OptionSpec& o) {
  return (c.name == "run" && (o.name == "--screenshot" || o.name == "--view" || o.name == "--size")) ||
         (c.name == "practice" && (o.name == "--window" || o.name == "--screenshot" || o.name == "--size")) ||
         (c.name == "validate" && (o.name == "--window" || o.name == "--screenshot" || o.name == "--size"));
}

// The usage lines: the table's forms, or "coilsim NAME OPERAND [options]".
std::string usageLines(const CommandSpec& c) {
  std::string forms(c.synopsis);
  if (forms.empty()) {  // appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "" + string chains
    forms = c.name;
    if (!c.operand.empty()) forms.append(" ").append(c.operand);
    if (c.maxOperands < 0) forms.append("...");
    if (!c.options.empty()) forms.append(" [options]");
  }
  std::string out;
  size_t at = 0;
  for (bool first = true; at <= forms.size(); first = false) {
    const size_t nl = std::min(forms.find('\n', at), forms.size());
    // A line that starts with blanks continues the form above it.
    const bool continued = forms[at] == ' ';
    out.append(first ? "usage: " : "       ").append(continued ? "        " : "coilsim ");
    out.append(forms, at, nl - at).append("\n");
    at = nl + 1;
  }
  return out;
}

std::string optionLine(const CommandSpec& c, const OptionSpec& o) {
  std::string head = "  ";
  head.append(o.name);
  if (!o.value.empty()) head.append(" ").append(o.value);
  std::string help(o.help);
  if (const std::string b = boundsOf(o); !b.empty() && o.kind != ValueKind::Size) help += " [" + b + "]";
  if (!haveUi() && needsUi(c, o)) help += " (not in this build: no ui layer)";
  if (head.size() < 24)
    head.resize(24, ' ');
  else
    head += "\n" + std::string(24, ' ');
  return head + help + "\n";
}

void printEffects(std::FILE* to) {
  std::fputs("effects a scene can switch on under \"effects\" (parameters: unit, default, range):\n", to);
  for (const Effect* e : EffectRegistry::global().all()) {
    std::fprintf(to, "  %-10s %s\n", std::string(e->name()).c_str(), std::string(e->description()).c_str());
    for (const ParamSpec& p : e->params())
      std::fprintf(to, "    %-22s %s, default %g, in [%g, %g]: %s\n", std::string(p.name).c_str(),
                   std::string(p.unit).c_str(), p.defaultValue, p.min, p.max, std::string(p.description).c_str());
  }
}

// The rod quantities, from their one declaration (physics/rod_quantities.h).
void printRodQuantities(std::FILE* to) {
  std::fputs("rod quantities: the same key in scene files, coil-measurement files and --fit (unit, range; * --fit "
             "can fit it):\n",
             to);
  const std::vector<const rodq::Quantity*> fit = validation::rodFitQuantities();
  for (const rodq::Quantity* q : rodq::kAll) {
    const ParamSpec& p = q->spec;
    const bool fits = std::find(fit.begin(), fit.end(), q) != fit.end();
    std::fprintf(to, "  %-18s %s %-5s in %c%g, %g]: %s\n", std::string(p.name).c_str(), fits ? "*" : " ",
                 std::string(p.unit).c_str(), q->minOpen ? '(' : '[', p.min, p.max, std::string(p.description).c_str());
  }
}

// A bash word list: "--out --input ...".
std::string words(const CommandSpec& c) {
  std::string w = "--help";
  for (const OptionSpec& o : c.options) w.append(" ").append(o.name);
  return w;
}

// What to offer for a value of this kind, as a bash statement.
std::string completeValue(ValueKind k, std::string_view choices) {
  switch (k) {
    case ValueKind::Choice: {
      std::string w(choices);
      std::replace(w.begin(), w.end(), '|', ' ');
      return "COMPREPLY=($(compgen -W \"" + w + "\" -- \"$cur\"))";
    }
    case ValueKind::Coil:
      return "_coilsim_coils \"$cur\" single";
    case ValueKind::CoilList:
      return "_coilsim_coils \"$cur\" list";
    case ValueKind::JsonFile:
      return "_coilsim_files '!*.json'";
    case ValueKind::MeshFile:
      return "_coilsim_files ''";  // STL, OBJ, PLY or OFF in any case: every file is offered
    case ValueKind::OutFile:
      return "_coilsim_files ''";
    case ValueKind::Directory:
      return "COMPREPLY=($(compgen -d -- \"$cur\")); compopt -o filenames 2>/dev/null";
    default:
      return "COMPREPLY=()";  // a number or free text: nothing to offer
  }
}

}  // namespace

void printCommandHelp(const CommandSpec& c, std::FILE* to) {
  std::fputs(usageLines(c).c_str(), to);
  std::fprintf(to, "\n%s\n", std::string(c.summary).c_str());
  if (!c.options.empty()) {
    std::fputs("\noptions:\n", to);
    for (const OptionSpec& o : c.options) std::fputs(optionLine(c, o).c_str(), to);
  }
  if (!c.notes.empty()) std::fprintf(to, "\n%s\n", std::string(c.notes).c_str());
  if (c.name == "run") {
    std::fputc('\n', to);
    printEffects(to);
  }
  if (c.name == "run" || c.name == "validate" || c.name == "diagnose") {
    std::fputc('\n', to);
    printRodQuantities(to);
  }
}

void printMainHelp(std::FILE* to) {
  std::fputs("usage: coilsim COMMAND [options]    (coilsim COMMAND --help: that command alone)\n\ncommands:\n", to);
  for (const CommandSpec& c : commands())
    std::fprintf(to, "  %-12s %s\n", std::string(c.name).c_str(), std::string(c.summary).c_str());
  std::fputs("  --version    the version\n", to);
  for (const CommandSpec& c : commands()) {
    if (c.name == "help") continue;
    std::fprintf(to, "\n---- %s\n", std::string(c.name).c_str());
    std::fputs(usageLines(c).c_str(), to);
    for (const OptionSpec& o : c.options) std::fputs(optionLine(c, o).c_str(), to);
    if (!c.notes.empty()) std::fprintf(to, "%s\n", std::string(c.notes).c_str());
  }
  std::fputc('\n', to);
  printEffects(to);
  std::fputc('\n', to);
  printRodQuantities(to);
}

std::string bashCompletion() {
  std::string s =
      "# bash completion for coilsim; generated by `coilsim completion bash` from its command table.\n"
      "# Catalogue coils are asked of `coilsim completion coils` while completing.\n"
      "_coilsim_files() {\n"
      "  local IFS=$'\\n'\n"
      "  if [[ -n $1 ]]; then COMPREPLY=($(compgen -f -X \"$1\" -- \"$cur\") $(compgen -d -- \"$cur\"))\n"
      "  else COMPREPLY=($(compgen -f -- \"$cur\")); fi\n"
      "  compopt -o filenames 2>/dev/null\n"
      "}\n"
      "_coilsim_coils() {\n"
      "  local head=\"\" tail=\"$1\"\n"
      "  if [[ $2 == list && $1 == *[,+]* ]]; then head=\"${1%[,+]*}\"; head=\"${1:0:${#head}+1}\"; "
      "tail=\"${1:${#head}}\"; fi\n"
      "  local names; names=$(\"${COMP_WORDS[0]}\" completion coils 2>/dev/null)\n"
      "  COMPREPLY=($(compgen -P \"$head\" -W \"$names\" -- \"$tail\"))\n"
      "  [[ $2 == list ]] && compopt -o nospace 2>/dev/null\n"
      "  return 0\n"
      "}\n"
      "_coilsim() {\n"
      "  local cur=\"${COMP_WORDS[COMP_CWORD]}\" prev=\"${COMP_WORDS[COMP_CWORD-1]}\"\n"
      "  local commands=\"";
  for (const CommandSpec& c : commands()) s += std::string(c.name) + " ";
  s += "--help --version\"\n"
       "  if (( COMP_CWORD == 1 )); then\n"
       "    if [[ $cur == */* || $cur == *.json ]]; then _coilsim_files '!*.json'; return; fi\n"
       "    COMPREPLY=($(compgen -W \"$commands\" -- \"$cur\"))\n"
       "    return\n"
       "  fi\n"
       "  local cmd=\"${COMP_WORDS[1]}\"\n"
       "  case \"$cmd\" in *.json) cmd=run ;; esac\n"
       "  case \"$cmd $prev\" in\n";
  for (const CommandSpec& c : commands())
    for (const OptionSpec& o : c.options)
      if (o.kind != ValueKind::None)
        s += "    \"" + std::string(c.name) + " " + std::string(o.name) + "\") " + completeValue(o.kind, o.choices) +
             "; return ;;\n";
  s += "  esac\n"
       "  case \"$cmd\" in\n";
  for (const CommandSpec& c : commands()) {
    s += "    " + std::string(c.name) + ")\n";
    s.append("      if [[ $cur == -* ]]; then COMPREPLY=($(compgen -W \"").append(words(c));
    s.append("\" -- \"$cur\")); return; fi\n");
    if (c.name == "help") {
      s += "      COMPREPLY=($(compgen -W \"$commands\" -- \"$cur\")) ;;\n";
    } else if (c.name == "completion") {
      s += "      COMPREPLY=($(compgen -W \"bash\" -- \"$cur\")) ;;\n";
    } else {
      s += "      " + completeValue(c.operandKind, "") + " ;;\n";
    }
  }
  s += "  esac\n"
       "}\n"
       "complete -F _coilsim coilsim\n";
  return s;
}

}  // namespace coilsim::app
