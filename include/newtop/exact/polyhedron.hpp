#pragma once
/// \file
/// Homogeneous polyhedron: a closed, consistently and outward oriented triangle mesh with a
/// density, and its potential in closed form (Werner & Scheeres 1997, "Exterior gravitation of a
/// polyhedron derived and compared with harmonic and mascon gravitation representations of
/// asteroid 4769 Castalia", Celest. Mech. Dyn. Astron. 65, 313–344).

#include <array>
#include <vector>

#include "newtop/core/types.hpp"
#include "newtop/exact/attraction.hpp"

namespace newtop {

using Triangle = std::array<int, 3>;

/// What to do with a mesh whose faces are not all oriented outwards.
enum class Orientation {
  check,     ///< reject a mesh that is not consistently oriented with outward normals
  reorient,  ///< make the orientation consistent and outward (flip faces as needed)
};

/// A validated homogeneous polyhedron with the per-face and per-edge data of the closed form.
/// Immutable; built by make().
class Polyhedron {
 public:
  /// Validates the mesh: indices in range, no degenerate triangle (repeated vertex or zero area),
  /// closed (every edge shared by exactly two faces), consistently oriented (each shared edge
  /// traversed once in each direction) and outward (positive signed volume). With
  /// Orientation::reorient, inconsistent or inward faces are flipped instead of rejected. Vertices
  /// no face uses are dropped. Throws InputError ("mesh: …") saying exactly what is wrong and
  /// where.
  static Polyhedron make(std::vector<Vec3> vertices, std::vector<Triangle> faces, double density,
                         Orientation orientation = Orientation::check);

  const std::vector<Vec3>& vertices() const { return vertices_; }
  const std::vector<Triangle>& faces() const { return faces_; }
  double density() const { return density_; }
  /// Enclosed volume (positive).
  double volume() const { return volume_; }
  /// D = ∫ ρ dm = σ/24 Σ_f det(a, b, c) (a + b + c) over the tetrahedra (O, a, b, c) of the faces,
  /// summed in twice the working precision and rounded once: a centre of mass that nearly
  /// vanishes keeps its relative accuracy, which the moment far away needs (its dipole term is
  /// D/R² against the quadrupole's r²/R³).
  const Vec3& first_moment() const { return first_moment_; }
  /// Number of faces flipped by Orientation::reorient (0 with Orientation::check).
  int flipped_faces() const { return flipped_; }

  /// Per-edge data of the closed form: end points and the symmetric dyad
  /// E_e = n_A n_A,eᵀ + n_B n_B,eᵀ (face normals times outward edge normals), stored as
  /// (xx, yy, zz, xy, xz, yz), and the edge's length.
  struct Edge {
    int i, j;
    double length;
    std::array<double, 6> E;
  };
  const std::vector<Edge>& edges() const { return edges_; }
  /// Unit outward normal of each face.
  const std::vector<Vec3>& normals() const { return normals_; }

  /// The closed form's data as structure-of-arrays streams, built once by make(), so that an
  /// evaluation reads contiguous arrays and gathers only the distances |r| of the vertices
  /// (docs/performance.md). With a, b, c the vertices of face f, N_f = (b − a) × (c − a):
  /// r_a·(r_b × r_c) = N_f·r_a = |N_f| (n_f·r_a), n_f·r_a = h_f − n_f·x, and
  /// r_b·r_c = (|r_b|² + |r_c|² − |c − b|²)/2. With v_i the first end of edge e (E_e v_j = E_e
  /// v_i), E_e r = c_e − E_e x and r·E_e r = k_e − 2 c_e·x + x·E_e x.
  struct Streams {
    std::vector<double> vx, vy, vz;        ///< vertex coordinates
    std::vector<int> fa, fb, fc;           ///< the vertices a, b, c of each face
    std::vector<double> nx, ny, nz;        ///< n_f
    std::vector<double> h;                 ///< h_f = n_f·a
    std::vector<double> area2;             ///< |N_f|, twice the face's area
    std::vector<double> bc2, ca2, ab2;     ///< |c − b|², |a − c|², |b − a|²
    std::vector<int> ei, ej;               ///< end points of each edge
    std::vector<double> length;            ///< |v_j − v_i|
    std::array<std::vector<double>, 6> E;  ///< E_e as (xx, yy, zz, xy, xz, yz)
    std::vector<double> cx, cy, cz;        ///< c_e = E_e v_i
    std::vector<double> k;                 ///< k_e = v_i·E_e v_i
  };
  const Streams& streams() const { return streams_; }

 private:
  Polyhedron() = default;
  /// Throws InputError when the volume, mass or inertia tensor overflows.
  static void check_mass_properties(const Polyhedron& p);
  std::vector<Vec3> vertices_;
  std::vector<Triangle> faces_;
  std::vector<Vec3> normals_;
  std::vector<Edge> edges_;
  Streams streams_;
  double density_ = 0.0;
  double volume_ = 0.0;
  Vec3 first_moment_ = Vec3::Zero();
  int flipped_ = 0;
};

/// Φ(x) = σ ∫ dV / |x − ρ| and ∇Φ(x) of the polyhedron in closed form (Werner–Scheeres):
/// Φ = σ/2 [Σ_e r_e·E_e r_e L_e − Σ_f (n_f·r_f)² ω_f], ∇Φ = σ [−Σ_e E_e r_e L_e + Σ_f n_f (n_f·r_f)
/// ω_f], r = vertex − x, L_e = ln((a + b + e)/(a + b − e)), ω_f the signed solid angle of face f.
/// Valid everywhere except on the surface's edges and vertices. The faces and edges are summed in
/// fixed blocks, each in a fixed order, so the result has the same bits for any number of threads.
/// threads > 1 evaluates blocks in parallel with OpenMP (where available). The moment is ∇Φ × x:
/// the closed form does not separate the monopole, so it carries the sums' cancellation, about
/// C ε (|x|/r)⁴ relative (exact_field.hpp uses the multipole series far from the body).
Attraction attraction(const Polyhedron& p, const Vec3& x, int threads = 1);

/// The gravity-gradient tensor in closed form (Werner–Scheeres): ∇∇Φ = σ [Σ_e E_e L_e − Σ_f F_f
/// ω_f], F_f = n_f n_fᵀ (trace −4πσ inside, 0 outside), valid off the surface; the moment's
/// Jacobian [∇Φ]× − [x]× ∇∇Φ from it. Same blocks and bits for any thread count as attraction().
GravityGradient gravity_gradient(const Polyhedron& p, const Vec3& x, int threads = 1);

}  // namespace newtop
