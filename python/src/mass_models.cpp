// Mass models (docs/model.md §2) from Python, and the exact and multipole models on them.

#include "newtop/exact/mass_models.hpp"

#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <memory>

#include "bindings.hpp"
#include "newtop/io/mesh.hpp"
#include "newtop/model/model.hpp"

namespace py = pybind11;

namespace newtop::python {
namespace {

/// A mass model shared by the models built on it.
struct PyMassModel {
  std::shared_ptr<const MassModel> model;
};

PyMassModel wrap(MassModel m) { return {std::make_shared<const MassModel>(std::move(m))}; }

const char* kind(const MassModel& m) {
  return std::holds_alternative<PointMasses>(m)  ? "points"
         : std::holds_alternative<Polyhedron>(m) ? "polyhedron"
                                                 : "ellipsoid";
}

}  // namespace

void bind_mass_models(py::module_& m) {
  py::class_<PyMassModel>(m, "MassModel",
                          "A mass model (docs/model.md §2): point masses, a homogeneous polyhedron "
                          "(a mesh file or vertices and faces, or a box) or a homogeneous "
                          "ellipsoid, in the user's frame.")
      .def_static(
          "point_masses",
          [](std::vector<double> masses, std::vector<Vec3> positions) {
            return wrap(PointMasses(std::move(masses), std::move(positions)));
          },
          py::arg("masses"), py::arg("positions"), "Point masses m_i > 0 at rho_i (N x 3).")
      .def_static(
          "point_masses_file",
          [](const std::string& path) { return wrap(io::read_point_masses(path)); },
          py::arg("path"),
          "Point masses from a CSV file of lines m, x, y, z (docs/exact_field.md).")
      .def_static(
          "polyhedron",
          [](std::vector<Vec3> vertices, std::vector<std::array<int, 3>> faces, double density) {
            return wrap(Polyhedron::make(std::move(vertices), std::move(faces), density));
          },
          py::arg("vertices"), py::arg("faces"), py::arg("density"),
          "A homogeneous polyhedron: vertices (N x 3), outward triangles (K x 3, 0-based), "
          "density > 0; the mesh is checked (closed, oriented, outward).")
      .def_static(
          "polyhedron_file",
          [](const std::string& path, double density, double scale) {
            return wrap(io::load_polyhedron(path, density, scale));
          },
          py::arg("path"), py::arg("density"), py::arg("scale") = 1.0,
          "A homogeneous polyhedron from a mesh file (OFF, PLY, STL, OBJ, TetGen .node/.face), "
          "coordinates multiplied by scale.")
      .def_static(
          "box",
          [](const Vec3& dimensions, double density, const Vec3& center) {
            return wrap(make_box(dimensions, density, center));
          },
          py::arg("dimensions"), py::arg("density"), py::arg("center") = Vec3::Zero().eval(),
          "A homogeneous box of these edge lengths along the frame's axes.")
      .def_static(
          "ellipsoid",
          [](const Vec3& semi_axes, double density, const Vec3& center) {
            return wrap(Ellipsoid::make(semi_axes, density, center));
          },
          py::arg("semi_axes"), py::arg("density"), py::arg("center") = Vec3::Zero().eval(),
          "A homogeneous ellipsoid of these semi-axes along the frame's axes.")
      .def_property_readonly(
          "kind", [](const PyMassModel& x) { return kind(*x.model); },
          "'points', 'polyhedron' or 'ellipsoid'")
      .def_property_readonly("mass",
                             [](const PyMassModel& x) { return mass_properties(*x.model).mass; })
      .def_property_readonly(
          "center_of_mass",
          [](const PyMassModel& x) { return mass_properties(*x.model).center_of_mass; })
      .def_property_readonly(
          "inertia_tensor",
          [](const PyMassModel& x) { return mass_properties(*x.model).inertia_tensor; },
          "the inertia tensor about the frame's origin O")
      .def_property_readonly("max_radius",
                             [](const PyMassModel& x) { return max_radius(*x.model); });

  auto model = py::reinterpret_borrow<py::class_<Model>>(m.attr("Model"));
  model
      .def_static(
          "exact",
          [](const PyMassModel& mm, double mu, double R, const Vec3& gyrostat) {
            return Model::exact(mm.model, mu, R, gyrostat);
          },
          py::arg("mass_model"), py::arg("mu"), py::arg("R"),
          py::arg("gyrostat") = Vec3::Zero().eval(),
          "The exact field of a centre of parameter mu at distance R (docs/model.md §2) on the "
          "body "
          "of the mass model (its principal axes at O).")
      .def_static(
          "multipole",
          [](const PyMassModel& mm, int order, double mu, double R, const Vec3& gyrostat) {
            return Model::multipole(mm.model, order, mu, R, gyrostat);
          },
          py::arg("mass_model"), py::arg("order"), py::arg("mu"), py::arg("R"),
          py::arg("gyrostat") = Vec3::Zero().eval(), "Its multipole expansion of order p.")
      .def_static(
          "quadratic_on",
          [](const PyMassModel& mm, const QuadraticField& f, const Vec3& gyrostat) {
            return Model::quadratic(mm.model, f, gyrostat);
          },
          py::arg("mass_model"), py::arg("field"), py::arg("gyrostat") = Vec3::Zero().eval(),
          "The quadratic field on the body of the mass model.");
}

}  // namespace newtop::python
