#pragma once
// The tubes of a frame as triangles, one mesh per rod role, each tube at the
// detail its size on screen needs (tubeDetail) and kept from frame to frame
// while its centre line, colours, radius and detail stay the same: a coil
// at rest, a paused session or a coil detached in the sac is not built
// again, and a role none of whose tubes changed is not uploaded again.
// GL-free, tested in tests/render.
#include <functional>
#include <vector>

#include "physics/draw_data.h"
#include "render/geometry.h"

namespace coilsim::render {

inline constexpr int kTubeRoles = 3;  // coil, catheter, wire

// 0 coil, 1 catheter, 2 wire.
int tubeRoleIndex(RodRole role);

class TubeCache {
 public:
  // Pixels on screen per metre at a tube, where it is nearest the eye; 0
  // (or no function) draws every tube at the full detail `most`.
  using PixelScale = std::function<double(const DrawTube&)>;

  // Builds the roles' meshes for `tubes`, reusing each tube's triangles
  // when nothing of it changed (`reuse` false: every tube built anew, the
  // renderer as it was before the cache).
  void update(const std::vector<DrawTube>& tubes, const TubeOptions& most, const PixelScale& scale, bool reuse = true);

  const TriangleMesh& mesh(int role) const { return roles_[role]; }
  // Whether the role's mesh differs from the one before the last update.
  bool changed(int role) const { return changed_[role]; }
  // Tubes built (not reused) by the last update, for tests and benchmarks.
  int built() const { return built_; }

 private:
  struct Entry {
    DrawTube source;  // centre, colours, radius and role as built
    TubeOptions options;
    TriangleMesh mesh;
    bool built = false;
  };
  std::vector<Entry> entries_;  // by tube index
  TriangleMesh roles_[kTubeRoles];
  bool changed_[kTubeRoles] = {true, true, true};
  int built_ = 0;
};

}  // namespace coilsim::render
