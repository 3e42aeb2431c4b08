#pragma once
// `coilsim case edit CASE.json --window`: planning::CaseEditor in the case
// editor window (ui/case_editor_window.h), or one frame of it off-screen
// (--screenshot). The editing stays in CaseEditor; this wires its moves,
// refusals and morphology to the window's plain hooks.
#include <string>

#include "planning/case_editor.h"
#include "ui/case_editor_window.h"

namespace coilsim::app {

// The window's hooks on `editor` (which must outlive them); Save writes
// `savePath`, asking first when it is the case file itself.
ui::CaseEditorHooks caseEditorHooks(planning::CaseEditor& editor, const std::string& caseFile,
                                    const std::string& savePath);

// What the window shows of the editor's case now: the vessel, the sac piece,
// the neck disc and normal, the catheter tip (m), the morphology rows.
ui::CaseEditorView caseEditorView(const planning::CaseEditor& editor);

}  // namespace coilsim::app
