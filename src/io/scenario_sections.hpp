#pragma once
// Internal: the sections of a scenario file (docs/scenario.md) and the checks that span them.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "newtop/io/scenario.hpp"
#include "newtop/model/attitude.hpp"
#include "toml_reader.hpp"

namespace newtop::io {

/// One input a derived quantity depends on, as `value^power`: the key that is named when the
/// quantity overflows.
struct Factor {
  std::string section;
  std::string key;
  double value = 0.0;
  int power = 1;
};

/// [field]: the quadratic field and how g and λ follow from the keys (for messages).
struct FieldSection {
  QuadraticField field;
  std::vector<Factor> g;       ///< |g| ∝ Π value^power
  std::vector<Factor> lambda;  ///< |λ| ∝ Π value^power
};

/// Every key [field] can hold.
const std::vector<std::string>& field_keys();

/// The centre of kind = "exact" | "multipole" as [field] gives it.
struct CentreSection {
  FieldKind kind = FieldKind::quadratic;
  double mu = 0.0, R = 0.0;
  int order = 0;
};

/// Reads [field] (kind optional where the keys say which field it is); fills `centre` for
/// kind = "exact" | "multipole", which need a mass model (`mass_model`, null without one).
/// `field` is then the quadratic field of the same μ and R (for the magnitude checks).
/// g_irrelevant (the body's r0 = 0): lambda without g is the field g = 0, lambda.
FieldSection read_field(TableReader& r, const std::shared_ptr<const MassModel>& mass_model,
                        CentreSection& centre, bool g_irrelevant);

/// A quaternion or rotation matrix given for the attitude must be a unit quaternion (|‖q‖ − 1|)
/// or orthonormal (max |RᵀR − I|) to this tolerance; it is then normalised (docs/scenario.md).
inline constexpr double kAttitudeTolerance = 1e-6;

/// The attitude keys of [initial]: quaternion, rotation_matrix, euler_321, euler_313.
const std::vector<std::string>& attitude_keys();

/// [initial]'s attitude (body → inertial, in the file's frame), or none when no attitude key is
/// given; more than one is bad input, named at the second. `normalize` (the [initial] key) lets a
/// quaternion of any non-zero norm be rescaled.
std::optional<Quaternion> read_attitude(TableReader& r, bool normalize);

/// Where the body's quantities come from: [body] keys, or the [mass_model] key that made them.
struct BodySource {
  Factor mass, center_of_mass, inertia, gyrostat;
};

/// The largest magnitude newtop lets a derived quantity reach: overflow (1.8e308) stays 1e8 away,
/// room for the sums of a few terms and the stages of an integrator.
inline constexpr double kMaxMagnitude = 1e300;

/// Checks that the potential's coefficients (M g r0, λI), the initial kinetic energy, m, ω, the
/// integrals, the moment and their bounds over the whole motion (from the conservation of
/// energy: ½ω·Iω ≤ T0 + 2 max|V|) stay below kMaxMagnitude; otherwise throws InputError naming the
/// key whose value drives the overflow, with the quantity and its inputs.
void check_magnitudes(const QuadraticModel& model, const State& x0, const FieldSection& field,
                      const BodySource& body, const toml::table& doc, const std::string& source);

}  // namespace newtop::io
