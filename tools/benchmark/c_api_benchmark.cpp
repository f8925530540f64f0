// The per-cell cost through the C API (include/gkt/gkt.h) against the direct C++ call, in pairs
// (docs/performance.md "C API"): the same inputs, the same work, the C call adding its argument
// checks and the exception barrier. Also χ(φ) exact (rationals) against double, and the batched
// calls (gkt_*_cells) against single calls on the same array of cells.
//
//   build/bin/gkt_benchmark --benchmark_filter='Cell' --benchmark_min_time=0.5
#include <benchmark/benchmark.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <numbers>

#include "gkt/cell.hpp"
#include "gkt/gkt.h"
#include "gkt/transport/common/pair_correlation.hpp"

namespace {

/// Returns the next α of the sweep 0.5 … 0.99 (a new input every call).
double next(double x) { return x < 0.99 ? x + 1e-3 : 0.5; }

void CellFirstSonineCpp(benchmark::State& state) {
  double alpha = 0.5;
  for (auto _ : state) {
    benchmark::DoNotOptimize(gkt::first_sonine_values(3, alpha));
    alpha = next(alpha);
  }
}
BENCHMARK(CellFirstSonineCpp)->Unit(benchmark::kNanosecond);

void CellFirstSonineC(benchmark::State& state) {
  double alpha = 0.5;
  gkt_first_sonine out;
  for (auto _ : state) {
    benchmark::DoNotOptimize(gkt_first_sonine_values(3, alpha, &out));
    benchmark::DoNotOptimize(out);
    alpha = next(alpha);
  }
}
BENCHMARK(CellFirstSonineC)->Unit(benchmark::kNanosecond);

/// The dense set at (α, φ) with χ(φ) in double: enskog_state + enskog_first_sonine_values.
void CellEnskogCpp(benchmark::State& state) {
  double alpha = 0.5;
  for (auto _ : state) {
    const double phi = 0.6 * (alpha - 0.5);  // 0 … 0.3
    benchmark::DoNotOptimize(gkt::enskog_first_sonine_values(3, alpha, gkt::enskog_state(3, phi)));
    alpha = next(alpha);
  }
}
BENCHMARK(CellEnskogCpp)->Unit(benchmark::kNanosecond);

void CellEnskogC(benchmark::State& state) {
  double alpha = 0.5;
  gkt_enskog_first_sonine out;
  for (auto _ : state) {
    const double phi = 0.6 * (alpha - 0.5);
    benchmark::DoNotOptimize(gkt_enskog_first_sonine_values(3, alpha, phi, &out));
    benchmark::DoNotOptimize(out);
    alpha = next(alpha);
  }
}
BENCHMARK(CellEnskogC)->Unit(benchmark::kNanosecond);

/// The batch against single calls on the same 256 cells per iteration (items = cells, so the
/// reported time per item is the per-cell cost): C++ loop, C single calls, one C batch call.
/// Arg 0 dilute, 1 dense (χ in double).
constexpr std::size_t batch_cells = 256;

struct BatchInputs {
  std::array<double, batch_cells> alpha{}, phi{};
  BatchInputs() {
    for (std::size_t i = 0; i < batch_cells; ++i) {
      alpha[i] = 0.5 + 0.49 * static_cast<double>(i) / (batch_cells - 1);
      phi[i] = 0.3 * static_cast<double>((i * 37) % batch_cells) / (batch_cells - 1);
    }
  }
};

void CellBatchCpp(benchmark::State& state) {
  const BatchInputs in;
  std::array<gkt::FirstSonineValues, batch_cells> dilute;
  std::array<gkt::EnskogFirstSonineValues, batch_cells> dense;
  for (auto _ : state) {
    if (state.range(0) == 0) {
      for (std::size_t i = 0; i < batch_cells; ++i) dilute[i] = gkt::first_sonine_values(3, in.alpha[i]);
      benchmark::DoNotOptimize(dilute.data());
    } else {
      for (std::size_t i = 0; i < batch_cells; ++i)
        dense[i] = gkt::enskog_first_sonine_values(3, in.alpha[i], gkt::enskog_state(3, in.phi[i]));
      benchmark::DoNotOptimize(dense.data());
    }
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * batch_cells));
}
BENCHMARK(CellBatchCpp)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

void CellBatchSingleC(benchmark::State& state) {
  const BatchInputs in;
  std::array<gkt_first_sonine, batch_cells> dilute;
  std::array<gkt_enskog_first_sonine, batch_cells> dense;
  for (auto _ : state) {
    if (state.range(0) == 0) {
      for (std::size_t i = 0; i < batch_cells; ++i)
        benchmark::DoNotOptimize(gkt_first_sonine_values(3, in.alpha[i], &dilute[i]));
      benchmark::DoNotOptimize(dilute.data());
    } else {
      for (std::size_t i = 0; i < batch_cells; ++i)
        benchmark::DoNotOptimize(gkt_enskog_first_sonine_values(3, in.alpha[i], in.phi[i], &dense[i]));
      benchmark::DoNotOptimize(dense.data());
    }
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * batch_cells));
}
BENCHMARK(CellBatchSingleC)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

void CellBatchC(benchmark::State& state) {
  const BatchInputs in;
  std::array<gkt_first_sonine, batch_cells> dilute;
  std::array<gkt_enskog_first_sonine, batch_cells> dense;
  for (auto _ : state) {
    if (state.range(0) == 0) {
      benchmark::DoNotOptimize(gkt_first_sonine_values_cells(3, batch_cells, in.alpha.data(), dilute.data()));
      benchmark::DoNotOptimize(dilute.data());
    } else {
      benchmark::DoNotOptimize(
          gkt_enskog_first_sonine_values_cells(3, batch_cells, in.alpha.data(), in.phi.data(), dense.data()));
      benchmark::DoNotOptimize(dense.data());
    }
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * batch_cells));
}
BENCHMARK(CellBatchC)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

/// χ(φ) and φ dχ/dφ: arg 0 exact (rationals from the double φ, rounded), 1 double.
void CellContactValue(benchmark::State& state) {
  const auto& closure = gkt::pair_correlation("carnahan-starling");
  double phi = 0.01;
  for (auto _ : state) {
    if (state.range(0) == 0) {
      const gkt::Rational exact = gkt::Rational::from_double(phi);
      benchmark::DoNotOptimize(closure.contact_value(3, exact).to_double());
      benchmark::DoNotOptimize(closure.packing_derivative(3, exact).to_double());
    } else {
      benchmark::DoNotOptimize(gkt::enskog_state(3, phi));
    }
    phi = phi < 0.49 ? phi + 1e-3 : 0.01;
  }
}
BENCHMARK(CellContactValue)->Arg(0)->Arg(1)->Unit(benchmark::kNanosecond);

/// The dilute binary table (order 1, 24 nodes), the full physical set at a new (x_1, n, T).
const gkt::BinaryTransportTable& cpp_table() {
  static const gkt::BinaryTransportTable table(gkt::make_mixture(3, {{1.0, 1.0, 0.5, ""}, {2.5, 1.5, 0.5, ""}}, 0.8),
                                               1);
  return table;
}

void CellBinaryTableCpp(benchmark::State& state) {
  const gkt::BinaryTransportTable& table = cpp_table();
  double x = 0.1;
  for (auto _ : state) {
    benchmark::DoNotOptimize(table.evaluate(x, 1.0 + x, 2.0 - x));
    x = x < 0.9 ? x + 1e-3 : 0.1;
  }
}
BENCHMARK(CellBinaryTableCpp)->Unit(benchmark::kNanosecond);

void CellBinaryTableC(benchmark::State& state) {
  static gkt_binary_table* table = [] {
    const double mass[2] = {1.0, 2.5}, diameter[2] = {1.0, 1.5}, alpha[4] = {0.8, 0.8, 0.8, 0.8};
    gkt_binary_table* t = nullptr;
    if (gkt_binary_table_create(3, mass, diameter, alpha, 1, 24, 0.0, 12, &t) != GKT_OK) t = nullptr;
    return t;
  }();
  if (table == nullptr) {
    state.SkipWithError(gkt_last_error());
    return;
  }
  double x = 0.1;
  gkt_binary_transport out;
  for (auto _ : state) {
    benchmark::DoNotOptimize(gkt_binary_table_evaluate(table, x, 1.0 + x, 2.0 - x, &out));
    benchmark::DoNotOptimize(out);
    x = x < 0.9 ? x + 1e-3 : 0.1;
  }
}
BENCHMARK(CellBinaryTableC)->Unit(benchmark::kNanosecond);

}  // namespace
