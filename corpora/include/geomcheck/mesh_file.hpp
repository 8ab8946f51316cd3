// geomcheck — mesh case files: bit-exact, versioned text reproductions of one
// case of a mesh query (GEOMCHECK_MESH_QUERY_LIST of registry.hpp: today
// collide_cylinder_mesh), a cylinder and a triangle mesh.
//
// A mesh file is a sibling of the case file of casefile.hpp and follows all
// of its conventions (header line, NUMBER and TEXT grammar, '#' comments,
// escapes, "line N: ..." errors, hex floats with a "%.17g" comment,
// bit-exact round trip); only the body differs. Files live in
// corpora/seeds/<id>/ and corpora/regressions/<id>/NNNN-<slug>.case.
//
//   # geomcheck case file
//   geomcheck-case 1
//   query collide_cylinder_mesh
//   found-by hand
//   oracle-verdict overlapping
//   note a unit cylinder on a square of two faces
//   cylinder 0x0p+0 0x0p+0 0x0p+0 0x0p+0 0x0p+0 0x1p+0 0x1p+0   # 0 0 0 0 0 1 1
//   vertex -0x1p+1 -0x1p+1 0x1p-1   # -2 -2 0.5
//   vertex 0x1p+1 -0x1p+1 0x1p-1    # 2 -2 0.5
//   vertex 0x1p+1 0x1p+1 0x1p-1     # 2 2 0.5
//   vertex -0x1p+1 0x1p+1 0x1p-1    # -2 2 0.5
//   face 0 1 2
//   face 0 2 3
//   end
//
// Format, version 1 (lines, blanks, comments, control bytes, TEXT and
// NUMBER exactly as in casefile.hpp):
//
//   file      := header-line meta* cylinder-line (vertex-line | face-line)* "end" (blank|comment)*
//   header-line = "geomcheck-case" VERSION            first statement; VERSION = 1
//   meta      := "query" MESH-QUERY-ID                exactly once
//              | "found-by" TEXT                      at most once
//              | "oracle-verdict" VERDICT             at most once
//              | "note" TEXT                          any number; joined with "\n"
//   cylinder-line := "cylinder" NUMBER{7}             p (3), q (3), r: the
//                                                     first body statement, once
//   vertex-line := "vertex" NUMBER NUMBER NUMBER      x y z; vertex i is the
//                                                     i-th vertex line (from 0)
//   face-line   := "face" INDEX INDEX INDEX           three vertex indices
//
//   * Every meta line comes before the cylinder line; "query" is required
//     and must name a mesh query (a file of a pair query is a case file:
//     parse_case reads it; of delaunay_2d a point-set file).
//   * Vertex and face lines come in any order, any number of them (zero
//     included); the writer writes every vertex before the first face.
//   * INDEX is a decimal from 0 to 4294967295 without sign. An index need
//     not name a vertex of the file: a face with an index out of range is
//     an invalid mesh, which the query must answer as no overlap.
//   * VERDICT is the mesh's exact verdict, from its faces' (the certified
//     engine's): "overlapping" when a face overlaps, else "undecided" when
//     a face's distance is within the engine's width of 0 (either sign),
//     else "touching" when a face touches, else "separated". An invalid
//     mesh or cylinder has no verdict: a file of one records none (replay
//     fails a verdict filed on invalid input).
//   * At most kMaxMeshVertices vertex lines and kMaxMeshFaces face lines
//     ("line N: more than ... vertices (the limit of a mesh file)"), and the
//     whole file at most kMaxMeshFileBytes.
//
// Every parse error reads "line N: <what is wrong>"; for an error at the end
// of the file (missing "end"), N is the last line. The parser never throws
// (it is fuzzed: fuzz/fuzz_mesh_file.cpp). For every MeshFile f with
// !mesh_file_error(f): parse_mesh_file(write_mesh_file(f)).value == f bit
// for bit (-0.0, subnormals, +-inf, NaN sign and payload included).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "geomcheck/casefile.hpp"
#include "geomcheck/shapes.hpp"
#include "geomcheck/triangle_mesh.hpp"

namespace geomcheck {

/// Largest number of vertices and of faces a mesh file may hold.
inline constexpr std::size_t kMaxMeshVertices = 250000;
inline constexpr std::size_t kMaxMeshFaces = 500000;
/// Largest accepted mesh file, in bytes.
inline constexpr std::size_t kMaxMeshFileBytes = 64 * 1024 * 1024;

/// One case of a mesh query.
struct MeshFile {
  int version = kCaseFileVersion;
  std::string query = "collide_cylinder_mesh";  ///< a mesh query's id
  Cylinder cylinder;
  std::vector<Vec3> vertices;
  std::vector<MeshFace> faces;
  /// The mesh's exact verdict when filed (one of mesh_verdicts()), or empty
  /// when not recorded.
  std::string oracle_verdict;
  /// How it was found: "hand", "campaign seed=... case=...", ...
  std::string found_by;
  /// Free text; may span several lines.
  std::string note;
};

/// Bit-exact equality: coordinates compare by their bit patterns (so -0.0 !=
/// 0.0 and a NaN equals a NaN with the same bits).
bool operator==(const MeshFile& x, const MeshFile& y);
inline bool operator!=(const MeshFile& x, const MeshFile& y) { return !(x == y); }

/// Outcome of parse_mesh_file / load_mesh_file: the case, or an error
/// (BasicParseResult of casefile.hpp).
using MeshParseResult = BasicParseResult<MeshFile>;

/// The verdict words a mesh file may record: "overlapping", "touching",
/// "separated", "undecided" (mesh_checks.hpp's MeshTruth decides them).
std::vector<std::string_view> mesh_verdicts();

/// What makes `f` unwritable as a valid file (unsupported version, a query
/// that is not a mesh query, unknown verdict, too many vertices or faces,
/// a text beyond kMaxMeshFileBytes), or nullopt when it is valid.
std::optional<std::string> mesh_file_error(const MeshFile& f);

/// The case as file text (format above). Never fails; a file with
/// mesh_file_error(f) is written as faithfully as possible and will not parse.
std::string write_mesh_file(const MeshFile& f);

/// Parses mesh file text. Never throws.
MeshParseResult parse_mesh_file(std::string_view text);

/// Reads and parses a file. A parse error reads "<path>: line N: ...";
/// an unreadable file "cannot open case file '<path>': <reason>" (error_line 0).
MeshParseResult load_mesh_file(const std::filesystem::path& path);

/// Writes `f` to `path` (through a temporary file and a rename, so a reader
/// never sees half a file). Refuses a file with mesh_file_error(f). On
/// failure returns false and sets `error`.
bool save_mesh_file(const std::filesystem::path& path, const MeshFile& f, std::string& error);

/// The mesh of the file (its hierarchy built; invalid when a vertex is not
/// finite or an index out of range).
inline TriangleMesh mesh_of(const MeshFile& f) { return TriangleMesh(f.vertices, f.faces); }

/// libFuzzer input of fuzz_collide_cylinder_mesh that decodes to this case
/// in its raw mode, or nullopt when the case is beyond that mode's reach
/// (more than 31 vertices or 63 faces): mode byte 0x00, the vertex and face
/// counts, the cylinder's and the vertices' doubles (8 bytes little-endian
/// each), one byte per face index (an index out of range as the vertex count).
std::optional<std::string> fuzz_input_from_mesh(const MeshFile& f);

}  // namespace geomcheck
