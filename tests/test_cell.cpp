// The solver-facing batch calls of gkt/cell.hpp equal the single-cell calls they loop over, value
// for value, and refuse arrays of different lengths.
#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <vector>

#include "gkt/cell.hpp"
#include "gkt/transport/mixture/mixture.hpp"

namespace {

/// True if a and b hold the same bits (so nan equals nan and −0 differs from 0).
template <class T>
bool same_bits(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

}  // namespace

TEST(Cell, FirstSonineBatchEqualsSingleCalls) {
  const std::vector<double> alpha{0.1, 0.35, 0.5, 0.77, 0.9, 1.0};
  for (int d : {2, 3}) {
    std::vector<gkt::FirstSonineValues> out(alpha.size());
    gkt::first_sonine_values(d, alpha, out);
    for (std::size_t i = 0; i < alpha.size(); ++i) {
      const auto single = gkt::first_sonine_values(d, alpha[i]);
      EXPECT_TRUE(same_bits(out[i], single)) << "d = " << d << ", alpha = " << alpha[i];
      EXPECT_NE(out[i].shear_viscosity, 0.0);
    }
  }
  std::array<gkt::FirstSonineValues, 2> short_out{};
  EXPECT_THROW(gkt::first_sonine_values(3, alpha, short_out), std::invalid_argument);
}

TEST(Cell, EnskogFirstSonineBatchEqualsSingleCalls) {
  const std::vector<double> alpha{0.5, 0.8, 0.95};
  const std::vector<gkt::EnskogState> state{{0.1, 1.2, 0.26}, {0.25, 1.9, 1.1}, {0.0, 1.0, 0.0}};
  for (int d : {2, 3}) {
    std::vector<gkt::EnskogFirstSonineValues> out(alpha.size());
    gkt::enskog_first_sonine_values(d, alpha, state, out);
    for (std::size_t i = 0; i < alpha.size(); ++i) {
      const auto single = gkt::enskog_first_sonine_values(d, alpha[i], state[i]);
      EXPECT_TRUE(same_bits(out[i], single)) << "d = " << d << ", cell " << i;
    }
    // A different state per cell gives different values: the batch does not reuse one cell's state.
    EXPECT_NE(out[0].pressure, out[1].pressure);
  }
  std::vector<gkt::EnskogFirstSonineValues> out(alpha.size());
  EXPECT_THROW(gkt::enskog_first_sonine_values(3, alpha, std::span(state).first(2), out), std::invalid_argument);
}

TEST(Cell, BinaryTableBatchEqualsSingleCalls) {
  const gkt::Mixture m = gkt::make_mixture(3, {{1, 1, 0.5, ""}, {3, 1.5, 0.5, ""}}, 0.8);
  const gkt::BinaryTransportTable table(m, 1, 6);
  const std::vector<double> x1{0.0, 0.2, 0.55, 1.0}, n{1.0, 0.4, 2.5, 0.9}, temperature{1.0, 2.0, 0.3, 1.7};
  std::vector<gkt::BinaryTransport> out(x1.size());
  gkt::evaluate(table, x1, n, temperature, out);
  for (std::size_t i = 0; i < x1.size(); ++i)
    EXPECT_TRUE(same_bits(out[i], table.evaluate(x1[i], n[i], temperature[i]))) << "cell " << i;
  EXPECT_NE(out[1].shear_viscosity, out[2].shear_viscosity);
  EXPECT_THROW(gkt::evaluate(table, x1, std::span(n).first(3), temperature, out), std::invalid_argument);
  try {
    gkt::evaluate(table, x1, n, temperature, std::span(out).first(1));
    ADD_FAILURE() << "a short output span was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "out: must have the 4 cells of fraction_1, got 1");
  }
}
