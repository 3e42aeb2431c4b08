#pragma once
// Triangle geometry built on the CPU from the core's draw data: lit tubes
// around rod centre lines, spheres for points, arrows for vectors, smoothed
// mesh normals. GL-free so that it is tested without a context.
#include <cstdint>
#include <vector>

#include "physics/draw_data.h"

namespace coilsim::render {

struct Vertex {
  float position[3];  // m
  float normal[3];    // unit, outward
  float colour[4];    // linear RGBA
};

// Closed, consistently wound triangle soup: counter-clockwise seen from
// outside, so that front faces face the viewer (the X-ray pass relies on it).
struct TriangleMesh {
  std::vector<Vertex> vertices;
  std::vector<std::uint32_t> indices;  // (ntriangle x 3)
  void clear() {
    vertices.clear();
    indices.clear();
  }
};

struct TubeOptions {
  int sides = 16;     // vertices around the tube (silhouettes of thick coils stay round)
  int capRings = 3;   // rings of each hemispherical end cap
  double radiusScale = 1.0;
  // Extra rings per segment on a Catmull-Rom curve through the nodes, so
  // that a coarse centre line (few nodes per loop) still draws round loops.
  int subdivisions = 0;
};

// The detail a tube needs where it is drawn `radiusPixels` thick (its
// radius on screen) with nodes `segmentPixels` apart, at most `most`'s:
// sides so that the polygon strays from the circle by at most
// `toleranceRing` pixels (its sagitta r (1 - cos(pi / sides))), at least 6;
// rings between nodes so that no piece is longer than `longestPiece`
// pixels; cap rings one per 3 pixels of radius, at least one. A thin wire
// seen from afar needs a fraction of the triangles a close-up does, and
// software GL pays for every triangle.
TubeOptions tubeDetail(const TubeOptions& most, double radiusPixels, double segmentPixels,
                       double toleranceRing = 0.5, double longestPiece = 6.0);

// Appends a tube of radius tube.radius around tube.centre: rings at each node
// (and at `subdivisions` points between nodes)
// perpendicular to the centre-line tangent, oriented by parallel transport
// (robust to any twist of the material frames), smooth normals, per-node
// colours (the first colour, or the role's default, where colours are
// missing) and hemispherical caps, so the tube is closed. Tubes with fewer
// than two finite nodes or a non-positive radius add nothing.
void appendTube(const DrawTube& tube, const TubeOptions& options, TriangleMesh& out);

// The ring frames appendTube uses: unit tangent and unit normal per node.
void tubeFrames(const std::vector<Vec3>& centre, std::vector<Vec3>& tangents, std::vector<Vec3>& normals);

// A closed UV sphere.
void appendSphere(const Vec3& centre, double radius, const Colour& colour, TriangleMesh& out, int slices = 10,
                  int stacks = 6);

// A closed arrow from `from` along `vector`: a shaft of radius `radius` and a
// cone head three radii wide, a quarter of the length (at most).
void appendArrow(const Vec3& from, const Vec3& vector, double radius, const Colour& colour, TriangleMesh& out,
                 int sides = 10);

// Appends a draw mesh with area-weighted vertex normals.
void appendMesh(const DrawMesh& mesh, TriangleMesh& out);

}  // namespace coilsim::render
