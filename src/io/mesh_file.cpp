#include "io/mesh_file.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "io/json_reader.h"
#include "io/json_writer.h"
#include "io/units.h"

namespace coilsim::io {
namespace {

[[noreturn]] void fail(const std::string& file, const std::string& message) { throw InputError(file + ": " + message); }

std::string yesNo(bool b) { return b ? "yes" : "no"; }

// ---- Structure checks before assimp reads a file. Assimp trusts headers
// and indices: a PLY header promising 1e8 vertices makes it allocate and
// loop, a face index out of range reads out of bounds. So each format is
// walked here first, with counts checked against the limits and the bytes
// present, and every face index against the vertex count.

std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// Whitespace-separated tokens of a text, with the line of each for messages.
class Tokens {
 public:
  Tokens(std::string_view text, size_t at = 0) : text_(text), at_(at) {}
  // The next token, or empty at the end; stops at '\n' when `inLine`.
  std::string_view next(bool inLine = false) {
    while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_]))) {
      if (inLine && text_[at_] == '\n') return {};
      if (text_[at_] == '\n') ++line_;
      ++at_;
    }
    const size_t start = at_;
    while (at_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[at_]))) ++at_;
    return text_.substr(start, at_ - start);
  }
  // Skips to the start of the next line.
  void endLine() {
    while (at_ < text_.size() && text_[at_] != '\n') ++at_;
    if (at_ < text_.size()) ++at_, ++line_;
  }
  bool atEnd() const { return at_ >= text_.size(); }
  size_t line() const { return line_; }

 private:
  std::string_view text_;
  size_t at_;
  size_t line_ = 1;
};

bool toInteger(std::string_view t, long long& out) {
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), out);
  return ec == std::errc() && end == t.data() + t.size();
}

bool toNumber(std::string_view t, double& out) {
  // from_chars refuses "nan" and "inf" spelled differently by writers; a
  // non-finite coordinate is reported after reading, with the vertex count.
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), out);
  return (ec == std::errc() || ec == std::errc::result_out_of_range) && end == t.data() + t.size();
}

// A count from a header: a whole number in [0, limit].
size_t headerCount(const std::string& path, std::string_view token, size_t limit, const std::string& what) {
  long long n = 0;
  if (!toInteger(token, n) || n < 0)
    fail(path, "the header's " + what + " count is \"" + std::string(token) + "\", expected a whole number >= 0");
  if (size_t(n) > limit)
    fail(path, "the header declares " + std::to_string(n) + " " + what + "s, more than the limit of " +
                   std::to_string(limit) + " (docs/input-limits.md)");
  return size_t(n);
}

void checkIndex(const std::string& path, long long index, size_t vertices, const std::string& where) {
  if (index < 0)
    fail(path, where + ": vertex index " + std::to_string(index) + " is negative");
  if (size_t(index) >= vertices)
    fail(path, where + ": vertex index " + std::to_string(index) + " is out of range: the file has " +
                   std::to_string(vertices) + " vertices" +
                   (vertices ? " (0.." + std::to_string(vertices - 1) + ")" : ""));
}

// ASCII STL: three numbers after every "vertex" and "normal", and the
// closing "endsolid". Assimp throws on a malformed number and leaks the mesh
// and node it was filling (found by scripts/test-sanitize), so it is only
// given files that parse.
void checkAsciiStl(const std::string& path, std::string_view data) {
  Tokens tokens(data);
  bool closed = false;
  for (std::string_view t = tokens.next(); !t.empty(); t = tokens.next()) {
    if (t == "endsolid") closed = true;
    if (t != "vertex" && t != "normal") continue;
    const size_t line = tokens.line();
    for (int k = 0; k < 3; ++k) {
      const std::string_view n = tokens.next(true);
      double v = 0;
      if (!toNumber(n, v))
        fail(path, "line " + std::to_string(line) + ": \"" + std::string(t) + "\" needs three numbers, got \"" +
                       std::string(n) + "\"" + (n.empty() ? " (the line ends)" : ""));
    }
  }
  if (!closed) fail(path, "ASCII STL without \"endsolid\" (truncated)");
}

// Binary STL: an 80-byte header, a triangle count, 50 bytes per triangle.
// A file starting with "solid" whose size does not fit is ASCII STL, which
// assimp reads line by line (bounded by the file's size).
void checkStl(const std::string& path, std::string_view data) {
  const bool ascii = data.substr(0, 5) == "solid";
  if (data.size() < 84) {
    if (ascii) return checkAsciiStl(path, data);
    fail(path, "binary STL needs at least 84 bytes (header and triangle count), the file holds " +
                   std::to_string(data.size()));
  }
  uint32_t count = 0;
  std::memcpy(&count, data.data() + 80, 4);
  const uint64_t needed = 84 + 50 * uint64_t(count);
  if (needed == data.size()) {
    if (count == 0) fail(path, "the file holds no triangles (binary STL of 0 triangles)");
    if (count > kMaxMeshTriangles)
      fail(path, "binary STL of " + std::to_string(count) + " triangles, more than the limit of " +
                     std::to_string(kMaxMeshTriangles) + " (docs/input-limits.md)");
    return;
  }
  if (ascii) return checkAsciiStl(path, data);
  fail(path, "binary STL: the header declares " + std::to_string(count) + " triangles, which take " +
                 std::to_string(needed) + " bytes, but the file holds " + std::to_string(data.size()) +
                 " (truncated or not an STL file)");
}

// PLY: the header's elements and properties, then every record of the body
// (ASCII or binary), with the face lists' indices checked against the vertex count.
struct PlyProperty {
  std::string name;
  bool list = false;
  std::string countType, type;  // countType for lists only
};
struct PlyElement {
  std::string name;
  size_t count = 0;
  std::vector<PlyProperty> properties;
};

int plySize(const std::string& type) {
  static const std::pair<const char*, int> sizes[] = {
      {"char", 1},   {"uchar", 1},  {"int8", 1},   {"uint8", 1},   {"short", 2},  {"ushort", 2},
      {"int16", 2},  {"uint16", 2}, {"int", 4},    {"uint", 4},    {"int32", 4},  {"uint32", 4},
      {"float", 4},  {"float32", 4}, {"double", 8}, {"float64", 8}};
  for (const auto& [name, size] : sizes)
    if (type == name) return size;
  return 0;
}
bool plyInteger(const std::string& type) { return type.find("float") == std::string::npos && type != "double"; }
bool plySigned(const std::string& type) { return type[0] != 'u'; }

void checkPly(const std::string& path, std::string_view data) {
  size_t headerEnd = data.find("\nend_header");
  if (headerEnd == std::string_view::npos) fail(path, "PLY without an \"end_header\" line");
  ++headerEnd;
  // The header is text: a byte that is not (assimp loops forever on some, found by scripts/fuzz).
  for (size_t i = 0; i < headerEnd; ++i) {
    const unsigned char c = static_cast<unsigned char>(data[i]);
    if (!(c == '\n' || c == '\r' || c == '\t' || (c >= 0x20 && c < 0x7f)))
      fail(path, "PLY header holds a byte that is not text (" + std::to_string(int(c)) + ") at offset " + std::to_string(i));
  }
  size_t body = data.find('\n', headerEnd);
  if (body == std::string_view::npos) fail(path, "PLY: nothing after \"end_header\"");
  ++body;
  std::string format;
  std::vector<PlyElement> elements;
  Tokens h(data.substr(0, headerEnd));
  for (std::string_view word = h.next(); !word.empty(); word = h.next()) {
    const size_t line = h.line();
    const std::string at = "PLY header line " + std::to_string(line);
    if (word == "ply" || word == "comment" || word == "obj_info") {
      if (word != "ply") h.endLine();
    } else if (word == "format") {
      format = std::string(h.next(true));
      if (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian")
        fail(path, at + ": unknown format \"" + format + "\" (ascii, binary_little_endian or binary_big_endian)");
      h.endLine();
    } else if (word == "element") {
      PlyElement e;
      e.name = std::string(h.next(true));
      const std::string what = e.name == "vertex" ? "vertex" : e.name == "face" ? "face" : "\"" + e.name + "\" element";
      e.count = headerCount(path, h.next(true), e.name == "face" ? kMaxMeshTriangles : kMaxMeshVertices, what);
      elements.push_back(e);
    } else if (word == "property") {
      if (elements.empty()) fail(path, at + ": a property before any element");
      PlyProperty p;
      std::string type(h.next(true));
      if (type == "list") {
        p.list = true;
        p.countType = std::string(h.next(true));
        type = std::string(h.next(true));
        if (!plySize(p.countType) || !plyInteger(p.countType))
          fail(path, at + ": a list's count type must be an integer type, got \"" + p.countType + "\"");
      }
      if (!plySize(type)) fail(path, at + ": unknown property type \"" + type + "\"");
      p.type = type;
      p.name = std::string(h.next(true));
      elements.back().properties.push_back(p);
    } else {
      fail(path, at + ": unexpected \"" + std::string(word) + "\" in the header");
    }
  }
  if (format.empty()) fail(path, "PLY header without a \"format\" line");
  size_t vertices = 0;
  bool haveVertex = false;
  for (const PlyElement& e : elements)
    if (e.name == "vertex") {
      vertices = e.count, haveVertex = true;
      for (const char* axis : {"x", "y", "z"})
        if (std::none_of(e.properties.begin(), e.properties.end(), [&](const PlyProperty& p) { return p.name == axis; }))
          fail(path, std::string("PLY: the vertex element has no \"") + axis + "\" property");
    }
  if (!haveVertex) fail(path, "PLY without a vertex element");
  if (std::none_of(elements.begin(), elements.end(), [](const PlyElement& e) { return e.name == "face" && e.count > 0; }))
    fail(path, "the file holds no triangles (PLY without faces)");
  for (const PlyElement& e : elements)
    if (e.name == "face" &&
        std::none_of(e.properties.begin(), e.properties.end(), [](const PlyProperty& p) {
          return p.list && (p.name == "vertex_indices" || p.name == "vertex_index");
        }))
      fail(path, "PLY: the face element has no \"vertex_indices\" list");

  // Before walking: each record needs at least this many bytes, so a count
  // the file cannot hold is refused without reading it.
  const size_t left = data.size() - body;
  for (const PlyElement& e : elements) {
    size_t least = 0;
    for (const PlyProperty& p : e.properties)
      least += format == "ascii" ? 2 : size_t(p.list ? plySize(p.countType) : plySize(p.type));
    if (least && e.count > left / least)
      fail(path, "PLY: the header declares " + std::to_string(e.count) + " " + e.name + " records, but the " +
                     std::to_string(left) + " bytes after the header hold at most " + std::to_string(left / least));
  }

  const bool ascii = format == "ascii";
  const bool bigEndian = format == "binary_big_endian";
  size_t at = body;
  Tokens t(data, body);
  // One value of `type`: as a double, and whether it was there and well formed.
  auto value = [&](const std::string& type, double& out) -> bool {
    if (ascii) {
      const std::string_view tok = t.next();
      if (tok.empty()) return false;
      long long i = 0;
      if (plyInteger(type)) {
        if (!toInteger(tok, i)) return false;
        out = double(i);
        return true;
      }
      return toNumber(tok, out);
    }
    const int n = plySize(type);
    if (at + size_t(n) > data.size()) return false;
    // The bytes as an unsigned integer, most significant first.
    uint64_t u = 0;
    for (int k = 0; k < n; ++k)
      u = (u << 8) | static_cast<unsigned char>(data[at + size_t(bigEndian ? k : n - 1 - k)]);
    at += size_t(n);
    if (n == 4 && !plyInteger(type)) out = std::bit_cast<float>(uint32_t(u));
    else if (n == 8) out = std::bit_cast<double>(u);
    else if (!plySigned(type)) out = double(u);
    else out = double(int64_t(u << (64 - 8 * n)) >> (64 - 8 * n));  // sign-extended
    return true;
  };
  for (const PlyElement& e : elements) {
    const bool face = e.name == "face";
    for (size_t r = 0; r < e.count; ++r) {
      const std::string where = "PLY element " + e.name + " record " + std::to_string(r);
      for (const PlyProperty& p : e.properties) {
        double v = 0;
        if (!p.list) {
          if (!value(p.type, v))
            fail(path, where + ": property \"" + p.name + "\" missing or not a " + p.type +
                           " (the file ends early or holds fewer records than its header declares)");
          continue;
        }
        if (!value(p.countType, v) || v < 0 || v != std::floor(v))
          fail(path, where + ": list \"" + p.name + "\" has no valid length");
        const size_t n = size_t(v);
        // assimp aborts the process on a face of no vertex (found by scripts/fuzz).
        if (face && n < 3) fail(path, where + ": a face of " + std::to_string(n) + " vertices (a face needs at least 3)");
        if (!ascii && n * size_t(plySize(p.type)) > data.size() - at)
          fail(path, where + ": list \"" + p.name + "\" of " + std::to_string(n) + " values runs past the end of the file");
        for (size_t k = 0; k < n; ++k) {
          if (!value(p.type, v))
            fail(path, where + ": list \"" + p.name + "\" declares " + std::to_string(n) +
                           " values; value " + std::to_string(k) + " is missing or not a " + p.type);
          if (face && (p.name == "vertex_indices" || p.name == "vertex_index")) {
            if (!plyInteger(p.type)) fail(path, where + ": vertex indices must be of an integer type, got " + p.type);
            checkIndex(path, (long long)v, vertices, "face " + std::to_string(r));
          }
        }
      }
    }
  }
}

// OFF: "OFF", the counts "V F E", V vertex lines, F face lines "n i1 .. in".
void checkOff(const std::string& path, std::string_view data) {
  Tokens t(data);
  auto token = [&]() {
    std::string_view w = t.next();
    while (!w.empty() && w[0] == '#') t.endLine(), w = t.next();
    return w;
  };
  const std::string_view magic = token();
  if (magic.size() < 3 || magic.substr(magic.size() - 3) != "OFF") fail(path, "OFF file without the \"OFF\" keyword");
  const size_t nv = headerCount(path, token(), kMaxMeshVertices, "vertex");
  const size_t nf = headerCount(path, token(), kMaxMeshTriangles, "face");
  (void)token();  // edges, unused
  if (nf == 0) fail(path, "the file holds no triangles (OFF with 0 faces)");
  // Each vertex takes at least 3 numbers and 3 separators; each face 4.
  if (nv > data.size() / 6 || nf > data.size() / 8)
    fail(path, "OFF: the header declares " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
                   " faces, more than the file's " + std::to_string(data.size()) + " bytes can hold");
  for (size_t v = 0; v < nv; ++v) {
    for (int k = 0; k < 3; ++k) {
      double x = 0;
      if (!toNumber(token(), x))
        fail(path, "OFF vertex " + std::to_string(v) + " (line " + std::to_string(t.line()) +
                       "): expected 3 coordinates (the header declares " + std::to_string(nv) + " vertices)");
    }
    t.endLine();  // colours may follow
  }
  for (size_t f = 0; f < nf; ++f) {
    long long n = 0;
    const std::string where = "OFF face " + std::to_string(f) + " (line " + std::to_string(t.line()) + ")";
    if (!toInteger(token(), n) || n < 3 || n > 1000)
      fail(path, where + ": expected a vertex count in [3, 1000] (the header declares " + std::to_string(nf) + " faces)");
    for (long long k = 0; k < n; ++k) {
      long long i = 0;
      if (!toInteger(t.next(true), i)) fail(path, where + ": expected " + std::to_string(n) + " vertex indices");
      checkIndex(path, i, nv, "face " + std::to_string(f));
    }
    t.endLine();
  }
}

// OBJ: "v" lines and "f" lines whose references "v", "v/t", "v//n" or
// "v/t/n" (1-based, or negative counting back from the last one so far)
// must name a vertex, texture coordinate and normal of the file.
void checkObj(const std::string& path, std::string_view data) {
  size_t total[3] = {0, 0, 0};  // v, vt, vn
  for (Tokens t(data); !t.atEnd(); t.endLine()) {
    const std::string_view w = t.next(true);
    total[0] += w == "v", total[1] += w == "vt", total[2] += w == "vn";
  }
  if (total[0] > kMaxMeshVertices)
    fail(path, "OBJ of " + std::to_string(total[0]) + " vertices, more than the limit of " + std::to_string(kMaxMeshVertices));
  static const char* const kWhat[3] = {"vertex", "texture coordinate", "normal"};
  size_t seen[3] = {0, 0, 0}, faces = 0;
  for (Tokens t(data); !t.atEnd(); t.endLine()) {
    const size_t line = t.line();
    const std::string_view word = t.next(true);
    seen[0] += word == "v", seen[1] += word == "vt", seen[2] += word == "vn";
    if (word != "f") continue;
    if (++faces > kMaxMeshTriangles)
      fail(path, "OBJ of more than " + std::to_string(kMaxMeshTriangles) + " faces (the limit)");
    for (std::string_view ref = t.next(true); !ref.empty(); ref = t.next(true)) {
      const std::string where = "OBJ line " + std::to_string(line) + ", face vertex \"" + std::string(ref) + "\"";
      std::string_view rest = ref;
      for (int k = 0; k < 3; ++k) {
        const size_t slash = rest.find('/');
        const std::string_view part = rest.substr(0, slash);
        if (!part.empty() || k == 0) {
          long long i = 0;
          if (!toInteger(part, i) || i == 0)
            fail(path, where + ": expected a " + kWhat[k] + " index 1, 2, ... or -1, -2, ...");
          if (i < 0 && -i > (long long)seen[k])
            fail(path, where + ": relative " + kWhat[k] + " index " + std::to_string(i) + " reaches before the first (" +
                           std::to_string(seen[k]) + " so far)");
          if (i > 0 && size_t(i) > total[k])
            fail(path, where + ": " + kWhat[k] + " index " + std::to_string(i) + " is out of range: the file has " +
                           std::to_string(total[k]));
        }
        if (slash == std::string_view::npos) break;
        rest = rest.substr(slash + 1);
      }
    }
  }
}

void checkObjHasFaces(const std::string& path, std::string_view data) {
  for (Tokens t(data); !t.atEnd(); t.endLine())
    if (t.next(true) == "f") return;
  fail(path, "the file holds no triangles (OBJ without \"f\" lines)");
}

void checkStructure(const std::string& path, const std::string& data) {
  const std::string ext = lower(std::filesystem::path(path).extension().string());
  const std::string_view d(data);
  if (d.substr(0, 3) == "ply") return checkPly(path, d);
  if (ext == ".off") return checkOff(path, d);
  if (ext == ".stl") return checkStl(path, d);
  if (ext == ".obj") return checkObj(path, d), checkObjHasFaces(path, d);
  if (ext == ".ply") fail(path, "a .ply file that does not start with \"ply\"");
}

}  // namespace

MeshInspection inspectMeshFile(const std::string& path, double scaleToMm) {
  if (!(scaleToMm > 0) || !std::isfinite(scaleToMm))
    fail(path, "the scale to millimetres must be a finite number > 0, got " + std::to_string(scaleToMm));
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) fail(path, "no such mesh file");
  if (std::filesystem::is_directory(path, ec)) fail(path, "is a directory, not a mesh file (not a regular file)");
  if (!std::filesystem::is_regular_file(path, ec)) fail(path, "not a regular file");
  const auto bytes = std::filesystem::file_size(path, ec);
  if (ec) fail(path, "cannot read the mesh: " + ec.message());
  if (bytes > kMaxMeshFileBytes)
    fail(path, "the file holds " + std::to_string(bytes) + " bytes, more than the limit of " +
                   std::to_string(kMaxMeshFileBytes) + " for a mesh (docs/input-limits.md)");
  {
    std::ifstream in(path, std::ios::binary);
    std::string data(bytes, '\0');
    if (!in || !in.read(data.data(), std::streamsize(bytes))) fail(path, "cannot read the mesh");
    checkStructure(path, data);
  }

  Assimp::Importer importer;
  // Points and lines are dropped at import: a wall is made of triangles.
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const aiScene* scene = importer.ReadFile(
      path, aiProcess_ValidateDataStructure | aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                aiProcess_SortByPType | aiProcess_PreTransformVertices);
  if (!scene) fail(path, std::string("cannot read the mesh: ") + importer.GetErrorString());

  MeshInspection out;
  out.file = path;
  out.parts = int(scene->mNumMeshes);
  TriangleMesh raw;
  raw.name = std::filesystem::path(path).stem().string();
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* mesh = scene->mMeshes[m];
    const int base = int(raw.vertices.size());
    for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
      const aiVector3D& p = mesh->mVertices[v];
      raw.vertices.push_back(scaleToMm * Vec3(p.x, p.y, p.z));
    }
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      const aiFace& face = mesh->mFaces[f];
      if (face.mNumIndices != 3) continue;
      raw.triangles.emplace_back(base + int(face.mIndices[0]), base + int(face.mIndices[1]), base + int(face.mIndices[2]));
    }
  }
  if (raw.triangles.empty()) fail(path, "the file holds no triangles");
  if (raw.triangles.size() > kMaxMeshTriangles)
    fail(path, std::to_string(raw.triangles.size()) + " triangles, more than the limit of " +
                   std::to_string(kMaxMeshTriangles) + " (docs/input-limits.md)");
  for (const Eigen::Vector3i& t : raw.triangles)
    for (int k = 0; k < 3; ++k)
      if (t[k] < 0 || size_t(t[k]) >= raw.vertices.size())
        fail(path, "a face names vertex " + std::to_string(t[k]) + " of " + std::to_string(raw.vertices.size()));
  for (const Vec3& v : raw.vertices)
    if (!v.allFinite()) fail(path, "a vertex coordinate is not a finite number (or beyond a double once scaled)");
  // Parts of one surface (OBJ groups, STL solids) meet at identical vertices.
  out.mesh = geometry::weldVertices(raw, 0);
  out.report = geometry::analyseMesh(out.mesh);
  out.repaired = geometry::repairMesh(out.mesh, 0);
  // A wall of 0.014 mm is a file in metres read as millimetres; one of 1 km, in micrometres.
  const double extent = (out.report.upper - out.report.lower).maxCoeff();
  if (out.repaired.usable && !(extent >= kMinMeshExtentMm && extent <= kMaxMeshExtentMm)) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "the surface is %g mm across, outside [%g, %g] mm: ", extent, kMinMeshExtentMm,
                  kMaxMeshExtentMm);
    out.repaired.usable = false;
    out.repaired.reason = std::string(buf) + (extent < kMinMeshExtentMm
                                                  ? "is the file in metres? (scale_to_mm 1000, --scale-to-mm 1000)"
                                                  : "is the file in micrometres? (scale_to_mm 0.001, --scale-to-mm 0.001)");
  }
  return out;
}

std::string describeInspection(const MeshInspection& in) {
  const geometry::MeshReport& r = in.report;
  std::ostringstream s;
  s.precision(6);
  s << in.file << ": " << r.triangles << " triangles, " << r.vertices << " vertices";
  if (in.parts > 1) s << " in " << in.parts << " parts";
  s << "\n  bounds mm   [" << r.lower.x() << ", " << r.upper.x() << "] x [" << r.lower.y() << ", " << r.upper.y()
    << "] x [" << r.lower.z() << ", " << r.upper.z() << "]\n";
  s << "  closed      " << yesNo(r.closed());
  if (!r.closed())
    s << " (" << r.boundaryEdges << " boundary edges, " << r.nonManifoldEdges << " non-manifold edges)";
  s << "\n  oriented    " << yesNo(r.oriented());
  if (!r.oriented() && r.misorientedEdges) s << " (" << r.misorientedEdges << " edges with inconsistent triangles)";
  s << "\n  components  " << r.components << "\n  volume mm^3 " << r.volume
    << (r.closed() && r.oriented() ? (r.volume > 0 ? " (normals outward)" : " (normals inward)") : " (not meaningful: not closed and oriented)")
    << "\n";
  if (r.degenerateTriangles) s << "  degenerate  " << r.degenerateTriangles << " triangles\n";
  for (const std::string& a : in.repaired.actions) s << "  repair      " << a << "\n";
  if (in.repaired.usable)
    s << "  usable      yes" << (in.repaired.actions.empty() ? "" : ", after the repairs above") << "\n";
  else
    s << "  usable      no: " << in.repaired.reason << "\n";
  return s.str();
}

TriangleMesh loadMeshFile(const std::string& path, double scaleToMm) {
  MeshInspection in = inspectMeshFile(path, scaleToMm);
  if (!in.repaired.usable)
    fail(path, "cannot be used as a wall: " + in.repaired.reason + "\n" + describeInspection(in));
  TriangleMesh mesh = std::move(in.repaired.mesh);
  for (Vec3& v : mesh.vertices) v = Vec3(units::mmToM(v.x()), units::mmToM(v.y()), units::mmToM(v.z()));
  return mesh;
}

void writeBinaryStl(const TriangleMesh& mesh, const std::string& path) {
  // Binary STL: 80-byte header, uint32 count, then per triangle a float32
  // normal, three float32 vertices and a uint16 attribute (little endian).
  std::string data(80, '\0');
  const std::string header = "coilsim binary STL, millimetres: " + mesh.name;
  std::memcpy(data.data(), header.data(), std::min<size_t>(header.size(), 80));
  auto put = [&](const void* p, size_t n) { data.append(static_cast<const char*>(p), n); };
  const uint32_t count = uint32_t(mesh.triangles.size());
  put(&count, 4);
  data.reserve(84 + 50 * size_t(count));
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    Vec3 n = (b - a).cross(c - a);
    if (n.norm() > 0) n.normalize();
    for (const Vec3* v : std::initializer_list<const Vec3*>{&n, &a, &b, &c}) {
      const float xyz[3] = {float(v->x()), float(v->y()), float(v->z())};
      put(xyz, 12);
    }
    const uint16_t attribute = 0;
    put(&attribute, 2);
  }
  static_assert(std::endian::native == std::endian::little, "STL is little endian");
  writeFileAtomic(path, data);
}

std::string phantomSidecarPath(const std::string& stlPath) {
  std::filesystem::path p(stlPath);
  p.replace_extension(".phantom.json");
  return p.string();
}

namespace {
nlohmann::ordered_json vec(const Vec3& v) { return {v.x(), v.y(), v.z()}; }
}  // namespace

void writePhantomSidecar(const geometry::PhantomInfo& info, const std::string& path) {
  const geometry::PhantomSpec& s = info.spec;
  nlohmann::ordered_json j;
  j["format"] = "coilsim-phantom/1";
  j["description"] = "saccular aneurysm phantom made by coilsim phantom; lengths in mm";
  j["type"] = info.type;
  j["parameters"] = {{"sac_diameter_mm", s.sacDiameter},
                     {"sac_height_mm", info.sacRadii.z() * 2},
                     {"neck_width_mm", info.neckWidth},
                     {"dome_to_neck", s.sacDiameter / info.neckWidth},
                     {"lobes", s.lobes},
                     {"vessel_diameter_mm", s.vesselDiameter},
                     {"resolution_mm", s.resolution},
                     {"blend_mm", s.blend}};
  j["sac"] = {{"centre_mm", vec(info.sacCentre)},
              {"radii_mm", vec(info.sacRadii)},
              {"axis_u", vec(info.axisU)},
              {"axis_v", vec(info.axisV)},
              {"ideal_volume_above_neck_mm3", info.idealSacVolume}};
  nlohmann::ordered_json lobes = nlohmann::ordered_json::array();
  for (const geometry::Lobe& l : info.lobes) lobes.push_back({{"centre_mm", vec(l.centre)}, {"radii_mm", vec(l.radii)}});
  j["sac"]["lobes"] = lobes;
  j["neck"] = {{"point_mm", vec(info.neck.point)}, {"normal", vec(info.neck.normal)}, {"width_mm", info.neckWidth}};
  j["vessel_radius_mm"] = info.vesselRadius;
  writeFileAtomic(path, formatJson(j));
}

geometry::PhantomInfo readPhantomSidecar(const std::string& path) {
  const nlohmann::json doc = readJsonFile(path);
  const JsonNode root(doc, path);
  root.allowKeys({"format", "description", "type", "parameters", "sac", "neck", "vessel_radius_mm"});
  root.child("format").oneOf({"coilsim-phantom/1"});
  geometry::PhantomInfo info;
  info.type = root.child("type").oneOf({"sidewall", "curved", "bifurcation"});
  geometry::parseVesselType(info.type, info.spec.vessel);
  auto v3 = [](const JsonNode& n, const Bounds& b = Bounds::any()) {
    const auto a = n.vec3(b);
    return Vec3(a[0], a[1], a[2]);
  };
  const JsonNode p = root.child("parameters");
  p.allowKeys({"sac_diameter_mm", "sac_height_mm", "neck_width_mm", "dome_to_neck", "lobes", "vessel_diameter_mm",
               "resolution_mm", "blend_mm"});
  info.spec.sacDiameter = p.child("sac_diameter_mm").number(Bounds::positive());
  info.spec.sacHeight = p.child("sac_height_mm").number(Bounds::positive());
  info.spec.neckWidth = p.child("neck_width_mm").number(Bounds::positive());
  info.spec.domeToNeck = p.child("dome_to_neck").number(Bounds::positive());
  info.spec.lobes = int(p.child("lobes").integer(1, 100));
  info.spec.vesselDiameter = p.child("vessel_diameter_mm").number(Bounds::positive());
  info.spec.resolution = p.child("resolution_mm").number(Bounds::positive());
  info.spec.blend = p.child("blend_mm").number(Bounds::nonNegative());
  const JsonNode sac = root.child("sac");
  sac.allowKeys({"centre_mm", "radii_mm", "axis_u", "axis_v", "ideal_volume_above_neck_mm3", "lobes"});
  info.sacCentre = v3(sac.child("centre_mm"));
  info.sacRadii = v3(sac.child("radii_mm"), Bounds::positive());
  info.axisU = v3(sac.child("axis_u"));
  info.axisV = v3(sac.child("axis_v"));
  info.idealSacVolume = sac.child("ideal_volume_above_neck_mm3").number(Bounds::positive());
  for (const JsonNode& l : sac.child("lobes").items(1, 100, "an array of lobes")) {
    l.allowKeys({"centre_mm", "radii_mm"});
    info.lobes.push_back({v3(l.child("centre_mm")), v3(l.child("radii_mm"), Bounds::positive())});
  }
  const JsonNode neck = root.child("neck");
  neck.allowKeys({"point_mm", "normal", "width_mm"});
  info.neck.point = v3(neck.child("point_mm"));
  info.neck.normal = v3(neck.child("normal"));
  if (std::abs(info.neck.normal.norm() - 1) > 1e-6) neck.child("normal").expected("a unit vector");
  info.neckWidth = neck.child("width_mm").number(Bounds::positive());
  info.vesselRadius = root.child("vessel_radius_mm").number(Bounds::positive());
  return info;
}

}  // namespace coilsim::io
