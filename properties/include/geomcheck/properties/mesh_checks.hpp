// geomcheck — the checks of the mesh family (collide_cylinder_mesh), written
// once and run by the property suite (test_mesh), the fuzz target
// (fuzz_collide_cylinder_mesh), replay and the campaign.
//
// The mesh query is the triangle query over the faces the hierarchy and the
// face filter keep, so a subject's answer for a cylinder and a mesh is held
// to:
//   * robustness: invalid input (an invalid cylinder, a non-finite vertex,
//     an index out of range) gives no hit; a hit's contact is finite;
//     collide's hit is overlap's verdict;
//   * argument order: collide(mesh, cylinder) is the flipped answer;
//   * the deepest face, the definition checked face by face in index order:
//     the verdict is "some face overlaps" (the triangle query's verdict)
//     and the contact is the deepest face's own triangle answer, bit for
//     bit (the smallest index on ties);
//   * production only: its hierarchy and face filter give the answers of
//     its brute force over every face, bit for bit (overlap, hit, depth,
//     normal, point, face index);
//   * a subject with claims of its own (MeshClaims: a user's, through the
//     door) is held instead to what it claims, never to production's bits:
//     no robust hit missed under its own verdict band, the reported face's
//     contact judged as a triangle answer under its face claims, and the
//     deepest face read against the faces' certified penetration depths;
//   * the truth, face by face: a face the certified engine finds
//     overlapping beyond the verdict band is not missed, and the reported
//     face's contact meets every claim of collide_cylinder_triangle
//     (judge() of its evaluation). A face whose bounding box is apart from
//     the cylinder's (a strict gap in the coordinates' doubles, rounded
//     outwards) is separated without asking the engine.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "geomcheck/collide_cylinder_mesh.hpp"
#include "geomcheck/oracles/exact.hpp"
#include "geomcheck/properties/checks.hpp"

namespace geomcheck {

/// A case of the mesh query: a cylinder and a mesh's vertices and faces,
/// and the generator's mode that drew it.
struct MeshCase {
  Cylinder cyl;
  std::vector<Vec3> vertices;
  std::vector<MeshFace> faces;
  std::string mode;
};

/// What a subject of the mesh query claims (a user's, through the door);
/// without claims a subject is held to production's yardsticks (its
/// triangle query's answer and its brute force, bit for bit).
struct MeshClaims {
  /// The reported face's contact, as an answer of collide_cylinder_triangle
  /// for the cylinder and that face, is held to these claims and to the
  /// bounds of their precision (production's claims of that query by
  /// default: a consistent contact, double precision).
  Claims face = spec_of<QueryId::collide_cylinder_triangle>().claims;
  /// The contact is the deepest face's: the reported face's certified
  /// penetration depth times `deepest_ratio`, plus twice the face's depth
  /// bound, is at least every face's (checked only where every enclosure
  /// involved is certified).
  bool deepest = true;
  /// 0: from the face claims: 1 for a penetration depth, production's
  /// bound of a consistent contact's depth over the penetration depth for
  /// an upper bound (a subject choosing the face of its largest consistent
  /// depth may pick a face that much shallower).
  double deepest_ratio = 0;
  /// Invalid input (an invalid cylinder, a non-finite vertex, an index out
  /// of range) answered with no hit; without it such meshes are not asked.
  bool any_input = false;
};

/// A subject of the mesh query (production, a known-wrong variant, a user's
/// through the door): collide with the face index, and where given overlap
/// (else collide's hit) and the flipped argument order (else not checked).
struct MeshImpl {
  const char* name;
  Callable<bool(const Cylinder&, const TriangleMesh&)> overlap;
  Callable<Contact(const Cylinder&, const TriangleMesh&, std::uint32_t*)> collide;
  Callable<Contact(const TriangleMesh&, const Cylinder&, std::uint32_t*)> collide_flipped;
  /// Null: production's yardsticks; else the subject's own (MeshClaims).
  const MeshClaims* claims = nullptr;
};

/// Production's mesh query.
const MeshImpl& production_mesh();
/// The known-wrong variants of the mesh query (teeth: the checks must
/// catch each): "mesh_first_face" answers the lowest-index overlapping
/// face's contact instead of the deepest's.
const std::vector<const MeshImpl*>& mesh_variants();
/// The subject named `name` (production or a variant), or null.
const MeshImpl* mesh_subject(const std::string& name);

/// The exact verdict of the mesh, face by face: overlapping when a face
/// overlaps; else undecided when a face is (its distance within the
/// engine's width of 0, of either sign); else touching when a face
/// touches; else separated.
struct MeshTruth {
  bool valid = false;  ///< the cylinder and the mesh are valid
  oracle::Verdict verdict = oracle::Verdict::Separated;
  int faces_by_box = 0;     ///< faces found separated by their bounding boxes
  int faces_by_engine = 0;  ///< faces the certified engine decided
  bool robust_hit = false;  ///< some face overlaps beyond the verdict band
  std::string hit_text;     ///< that face and the engine's answer
  /// The evaluation of each face the engine decided (production's
  /// triangle query held to the truth), by face index; empty elsewhere.
  std::vector<std::optional<Evaluation>> faces;
};

/// The robustness, brute-force, argument-order and deepest-face checks
/// (no oracle): cheap, and exact (bit-identity and the triangle query's
/// own verdicts).
CheckResult check_mesh_consistency(const Cylinder& cyl, const TriangleMesh& mesh,
                                   const MeshImpl& impl = production_mesh());
/// The truth of the case, face by face (the certified engine on every face
/// its bounding box does not separate).
MeshTruth mesh_truth(const Cylinder& cyl, const TriangleMesh& mesh);
/// The truth's checks: no robust hit missed; the reported contact is the
/// reported face's triangle answer and is held to collide_cylinder_triangle's
/// claims. `truth` from mesh_truth.
CheckResult check_mesh_oracle(const Cylinder& cyl, const TriangleMesh& mesh, const MeshTruth& truth,
                              const MeshImpl& impl = production_mesh());
/// Every check, in order: consistency, then the truth (computed here, and
/// stored in *truth when given, also when the consistency checks fail).
CheckResult check_mesh_all(const Cylinder& cyl, const TriangleMesh& mesh, const MeshImpl& impl = production_mesh(),
                           MeshTruth* truth = nullptr);

/// The case in words: the cylinder and every vertex and face, coordinates
/// with round-trip precision ("%.17g").
std::string describe_mesh(const Cylinder& cyl, const std::vector<Vec3>& vertices, const std::vector<MeshFace>& faces);

}  // namespace geomcheck
