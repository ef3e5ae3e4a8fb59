#pragma once
// Integer lattices for the torus frequencies of brun_prym_periods.cpp (private to src/analysis):
// a basis of the lattice of R⁴ that a set of periods generates, and the lattice of R² of the flow
// times whose velocity vector lies in it.

#include <Eigen/Core>
#include <vector>

namespace newtop::prym_lattice {

/// A basis (columns) of the lattice the vectors generate: their coordinates in four independent
/// ones are rational with small denominators; integer row reduction (Euclid, column by column) of
/// the scaled rows. Throws InputError when the vectors span less than R⁴ or are not commensurate.
Eigen::Matrix4d lattice_basis(std::vector<Eigen::Vector4d> p);

/// Lagrange–Gauss reduction of a basis of a lattice of R².
void reduce(Eigen::Vector2d& a, Eigen::Vector2d& b);

/// The lattice {τ ∈ R² : W τ ∈ Λ} (columns of L a basis of Λ), reduced (columns). Throws
/// InputError when it is not of rank 2 within the integer combinations searched.
Eigen::Matrix2d torus_lattice(const Eigen::Matrix4d& L, const Eigen::Matrix<double, 4, 2>& W);

}  // namespace newtop::prym_lattice
