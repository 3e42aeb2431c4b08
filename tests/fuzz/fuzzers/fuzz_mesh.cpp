// libFuzzer entry point for the mesh reader (scripts/fuzz): the first byte
// picks the extension (.stl .ply .obj .off), the rest is written to a file
// and read by io::inspectMeshFile as `coilsim mesh` does. It may refuse the
// file only with io::InputError.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "io/json_reader.h"
#include "io/mesh_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  static const char* const kExtensions[] = {".stl", ".ply", ".obj", ".off"};
  const std::string path = "/tmp/coilsim-fuzz-mesh-" + std::to_string(getpid()) + kExtensions[data[0] % 4];
  if (std::FILE* f = std::fopen(path.c_str(), "wb")) {
    std::fwrite(data + 1, 1, size - 1, f);
    std::fclose(f);
  } else {
    return 0;
  }
  try {
    const coilsim::io::MeshInspection in = coilsim::io::inspectMeshFile(path);
    (void)coilsim::io::describeInspection(in);
  } catch (const coilsim::io::InputError&) {
  }
  std::remove(path.c_str());
  return 0;
}
