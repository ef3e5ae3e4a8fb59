// Throughput of the exact polyhedron field on Eros (14,744 faces): one evaluation of Φ and ∇Φ
// (Werner–Scheeres closed form), single core and with OpenMP over face/edge blocks, and the
// far-field series used from R ≥ 16 radii; the closed form on Eros with every triangle split in
// four, once or twice (58,976 and 235,904 faces: data that no longer fits in the caches).

#include <benchmark/benchmark.h>

#include <cstdint>
#include <map>

#include "newtop/exact/exact_field.hpp"
#include "newtop/io/mesh.hpp"

namespace {

const newtop::Polyhedron& eros() {
  static const newtop::Polyhedron p =
      newtop::io::load_polyhedron(std::string(NEWTOP_DATA_DIR) + "/polyhedra/eros.face", 1.0);
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

/// Eros with every triangle split into four at its edges' midpoints, `levels` times (the same
/// solid, four times the faces per level).
newtop::Polyhedron eros_subdivided(int levels) {
  std::vector<newtop::Vec3> v = eros().vertices();
  std::vector<newtop::Triangle> f = eros().faces();
  for (int l = 0; l < levels; ++l) {
    std::map<std::uint64_t, int> midpoint;
    auto mid = [&v, &midpoint](int a, int b) {
      const auto key = (static_cast<std::uint64_t>(std::min(a, b)) << 32) |
                       static_cast<std::uint64_t>(std::max(a, b));
      const auto [it, added] = midpoint.try_emplace(key, static_cast<int>(v.size()));
      if (added) v.push_back(0.5 * (v[a] + v[b]));
      return it->second;
    };
    std::vector<newtop::Triangle> g;
    for (const newtop::Triangle& t : f) {
      const int ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
      g.insert(g.end(), {{t[0], ab, ca}, {ab, t[1], bc}, {ca, bc, t[2]}, {ab, bc, ca}});
    }
    f = std::move(g);
  }
  return newtop::Polyhedron::make(std::move(v), std::move(f), 1.0);
}

void BM_ErosSubdividedClosedForm(benchmark::State& state) {
  const newtop::Polyhedron p = eros_subdivided(static_cast<int>(state.range(0)));
  newtop::Vec3 x(2.0, 0.5, 0.3);
  for (auto _ : state) {
    x.x() += 1e-9;
    benchmark::DoNotOptimize(newtop::attraction(p, x, 1));
  }
  state.counters["faces"] = static_cast<double>(p.faces().size());
  state.counters["s/face"] =
      benchmark::Counter(static_cast<double>(state.iterations() * p.faces().size()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_ErosSubdividedClosedForm)->Arg(1)->Arg(2)->Unit(benchmark::kMicrosecond);

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
