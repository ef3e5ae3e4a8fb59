// Throughput of the exact polyhedron field on Eros (14,744 faces): one evaluation of Φ and ∇Φ
// (Werner–Scheeres closed form), single core and with OpenMP over face/edge blocks, and the
// far-field series used from R ≥ 16 radii.

#include <benchmark/benchmark.h>

#include "newtop/exact/exact_field.hpp"
#include "newtop/io/mesh.hpp"

namespace {

const newtop::Polyhedron& eros() {
  static const newtop::Polyhedron p = newtop::io::load_polyhedron(
      std::string(NEWTOP_SHARED_DIR) + "/data/polyhedra/eros.face", 1.0);
  return p;
}

void BM_ErosClosedForm(benchmark::State& state) {
  const auto& p = eros();
  const int threads = static_cast<int>(state.range(0));
  newtop::Vec3 x(2.0, 0.5, 0.3);
  for (auto _ : state) {
    x.x() += 1e-9;  // a new point each time
    benchmark::DoNotOptimize(newtop::attraction(p, x, threads));
  }
  state.counters["faces"] = static_cast<double>(p.faces().size());
  state.counters["evals/s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ErosClosedForm)
    ->Arg(1)
    ->Arg(2)
    ->Arg(4)
    ->Arg(8)
    ->Arg(16)
    ->UseRealTime()
    ->Unit(benchmark::kMicrosecond);

void BM_ErosFarFieldSeries(benchmark::State& state) {
  auto model = std::make_shared<const newtop::MassModel>(eros());
  const newtop::ExactField f = newtop::ExactField::make(model, 1.0, 20.0);
  const newtop::Vec3 g = newtop::Vec3(0.3, 0.4, 0.5).normalized();
  for (auto _ : state) benchmark::DoNotOptimize(newtop::field_values(f, g));
  state.counters["order"] = f.far_order;
}
BENCHMARK(BM_ErosFarFieldSeries)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
