// Uses an installed newtop: every exported target and, through them, every dependency —
// newtop::newtop (Eigen, Boost.Math, OpenMP inside the library) and newtop::io (toml++,
// nlohmann-json). Built with -Wall -Wextra -Werror: the public headers compile clean.
// Exit 0 only when each part gives the expected answer.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <newtop/io/json.hpp>
#include <newtop/io/mesh.hpp>
#include <newtop/io/output.hpp>
#include <newtop/io/scenario.hpp>
#include <newtop/newtop.hpp>
#include <string>
#include <type_traits>

namespace {

using namespace newtop;

bool check(bool ok, const char* what) {
  std::printf("consumer: %-52s %s\n", what, ok ? "ok" : "FAILED");
  return ok;
}

/// newtop::newtop: a heavy top integrated by splitting4 conserves energy.
bool integrate_heavy_top() {
  const QuadraticModel model{Body::from_principal(Vec3(2, 2, 1), 1.0, Vec3(0, 0, 0.5)),
                             QuadraticField::uniform(9.81)};
  const State x0 = state_from_omega(model.body, Vec3(0.3, 0, 20), Vec3(0.6, 0, 0.8));
  SplittingStepper stepper(composition_table("splitting4"));
  const Outcome out = integrate(stepper, model, x0, 0.0, 10.0, IntegrateOptions{.step = 1e-3});
  // splitting4 at h = 1e-3 conserves this top's energy (~200) to ~1e-10 relative.
  const double drift = std::abs(energy(model, out.state) - energy(model, x0));
  return out.status == Status::finished && drift < 1e-6;
}

/// newtop::newtop: the README's snippet — a run compiled in the library (run.hpp, any Model)
/// takes the same steps as a stepper of one's own (splitting.hpp, driver.hpp) on the model's field.
bool readme_snippet() {
  const Model model(Body::from_principal(Vec3(1.0, 1.5, 2.2), 1.0, Vec3::Zero()),
                    QuadraticField::from_mu_R(398600.4418, 7000.0));
  const State x0 = state_from_omega(model.body(), Vec3(0.3, 0.4, 1.1), Vec3(0, 0.6, 0.8));
  const Outcome out = run_method({"splitting6", 0.01}, model, x0, 0.0, 10.0);
  SplittingStepper stepper(composition_table("splitting6"));
  const Outcome same =
      integrate(stepper, model.quadratic(), x0, 0.0, 10.0, IntegrateOptions{.step = 0.01});
  return out.status == Status::finished && out.steps == same.steps && out.state.m == same.state.m &&
         out.state.gamma == same.state.gamma;
}

/// newtop::newtop: the library refuses a state whose γ is not a unit vector.
bool refuses_non_unit_gamma() {
  const Model model(Body::from_principal(Vec3(1, 2, 3), 1.0, Vec3::Zero()), QuadraticField{});
  try {
    run_method({"splitting6", 0.01}, model, State{Vec3(0, 0, 1), Vec3(0, 0, 2)}, 0.0, 1.0);
  } catch (const InputError&) {
    return true;
  }
  return false;
}

/// newtop::newtop (Boost.Math elliptic functions): the Euler–Poinsot solution keeps |m| and the
/// energy of the free body and moves m.
bool euler_poinsot_solution() {
  const QuadraticModel model{Body::from_principal(Vec3(1, 2, 3), 1.0, Vec3::Zero()),
                             QuadraticField{}};
  const State x0 = state_from_omega(model.body, Vec3(0.3, 0.4, 1.1), Vec3(0, 0.6, 0.8));
  const State x = analytic_state(analytic_solution(model, x0, AnalyticKind::euler_poinsot), 2.0);
  // Elliptic functions to a few ulps: 1e-12 relative leaves a wide margin.
  return (x.m - x0.m).norm() > 0.1 && std::abs(x.m.norm() - x0.m.norm()) < 1e-12 &&
         std::abs(energy(model, x) - energy(model, x0)) < 1e-12;
}

/// newtop::newtop: an exact field plugged into Model through the umbrella header: visit_model hands
/// the concrete BasicModel<ExactField>, and the compiled run takes the same steps as a stepper of
/// one's own on exact_model(model).
bool exact_field_model() {
  const auto points = std::make_shared<const MassModel>(PointMasses(
      {1.0, 0.7, 0.5}, {Vec3(0.3, 0.1, -0.2), Vec3(-0.4, 0.2, 0.1), Vec3(0.1, -0.5, 0.3)}));
  const Model model = Model::exact(points, 1.0, 5.0);
  const bool concrete = visit_model(model, [](const auto& m) {
    return std::is_same_v<std::decay_t<decltype(m)>, BasicModel<ExactField>>;
  });
  const State x0 = state_from_omega(model.body(), Vec3(0.1, 0.2, 0.3), Vec3(0.0, 0.6, 0.8));
  const Outcome out = run_method({"splitting6", 0.01}, model, x0, 0.0, 1.0);
  SplittingStepper stepper(composition_table("splitting6"));
  const Outcome same =
      integrate(stepper, exact_model(model), x0, 0.0, 1.0, IntegrateOptions{.step = 0.01});
  return concrete && out.status == Status::finished && out.steps == same.steps &&
         out.state.m == same.state.m && out.state.gamma == same.state.gamma;
}

/// newtop::io (toml++): a scenario parsed from text.
bool parse_scenario_text() {
  const io::Scenario sc = io::parse_scenario(
      "[body]\ninertia = [1.0, 1.5, 2.2]\nmass = 1.0\n[field]\ng = 1.0\nlambda = 1.0\n"
      "[initial]\nomega = [0.0, 0.0, 1.2]\ngamma = [0.0, 0.0, 1.0]\n",
      "consumer.toml");
  return sc.model.body().C() == 2.2 && sc.model.quadratic().field.lambda_ == 1.0;
}

/// newtop::io (nlohmann-json): a vector as JSON.
bool vector_json() { return io::to_json(Vec3(1, 2, 3)).dump() == "[1.0,2.0,3.0]"; }

/// newtop::io (its mesh readers) and the polyhedron (OpenMP): the unit corner tetrahedron from an
/// OBJ file has volume 1/6, so mass density/6.
bool tetrahedron_from_obj() {
  const auto path = std::filesystem::temp_directory_path() / "newtop_consumer_tetrahedron.obj";
  std::ofstream(path) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                         "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  const io::Mesh mesh = io::read_mesh(path.string());
  const double mass = mass_properties(io::load_polyhedron(path.string(), 6.0)).mass;
  std::filesystem::remove(path);
  return mesh.vertices.size() == 4 && mesh.faces.size() == 4 && std::abs(mass - 1.0) < 1e-14;
}

}  // namespace

int main() {
  bool ok = check(integrate_heavy_top(), "newtop::newtop: heavy top, energy conserved");
  ok = check(readme_snippet(), "newtop::newtop: README snippet, compiled = template") && ok;
  ok = check(refuses_non_unit_gamma(), "newtop::newtop: non-unit gamma refused") && ok;
  ok = check(NEWTOP_VERSION >= 100 && std::string(NEWTOP_VERSION_STRING).size() >= 5,
             "newtop::newtop: NEWTOP_VERSION") &&
       ok;
  ok = check(euler_poinsot_solution(), "newtop::newtop: Euler-Poinsot solution") && ok;
  ok = check(exact_field_model(), "newtop::newtop: exact field, compiled = template") && ok;
  ok = check(parse_scenario_text(), "newtop::io: scenario from TOML text") && ok;
  ok = check(vector_json(), "newtop::io: JSON") && ok;
  ok = check(tetrahedron_from_obj(), "newtop::io: OBJ mesh, polyhedron mass") && ok;
  return ok ? 0 : 1;
}
