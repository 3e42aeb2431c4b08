// libFuzzer entry point for the JSON readers (scripts/fuzz). The first byte
// picks the reader, the rest is the file's text. A reader may refuse its
// input only with io::InputError; anything else (another exception, a
// crash, a sanitizer report, a hang) is a finding.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "io/coil_catalogue.h"
#include "io/json_reader.h"
#include "io/measurement.h"
#include "io/scene.h"
#include "io/timeline.h"
#include "planning/case_file.h"
#include "planning/practice.h"

namespace {

// Inputs are labelled as files of the corpus directory, so that a relative
// path inside them (a scene's mesh, a case's scene) stays in the corpus.
const std::string kLabel = std::string(COILSIM_FUZZ_CORPUS) + "/fuzz-input.json";

void readAs(uint8_t which, std::string_view text) {
  using namespace coilsim;
  switch (which % 6) {
    case 0: {
      const io::SceneSpec s = io::parseScene(io::parseJson(text, kLabel), kLabel);
      io::checkScene(s);
      break;
    }
    case 1: (void)io::timelineFromText(text, kLabel); break;
    case 2: (void)io::parseMeasurement(text, kLabel); break;
    case 3: (void)io::coilFromText(text, kLabel); break;
    case 4: (void)planning::parseSession(io::parseJson(text, kLabel), kLabel); break;
    case 5: {
      // A case reads the catalogue from disk; only cases that name no other
      // file are worth the time (inline scene, sphere sac).
      const nlohmann::json doc = io::parseJson(text, kLabel);
      (void)planning::parseCase(doc, kLabel);
      break;
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  try {
    readAs(data[0], std::string_view(reinterpret_cast<const char*>(data + 1), size - 1));
  } catch (const coilsim::io::InputError&) {
    // A refusal with a message: what a reader should do.
  }
  return 0;
}
