// A minimal row-major dense matrix for exact element types (Rational, RationalPolynomial).
// Floating-point linear algebra uses Eigen; exact linear algebra uses FLINT (fmpq_mat).
#pragma once

#include <cassert>
#include <vector>

namespace gkt {

/// Row-major rows × cols matrix of T with value semantics.
template <class T>
class DenseMatrix {
 public:
  DenseMatrix() = default;
  /// A rows × cols matrix of value-initialised T (zero for Rational / RationalPolynomial).
  DenseMatrix(int rows, int cols) : rows_(rows), cols_(cols), data_(static_cast<std::size_t>(rows) * cols) {}
  /// Returns the number of rows.
  [[nodiscard]] int rows() const { return rows_; }
  /// Returns the number of columns.
  [[nodiscard]] int cols() const { return cols_; }
  /// Returns entry (r, c), zero-based, writable (bounds asserted in debug builds).
  T& operator()(int r, int c) {
    assert(r >= 0 && r < rows_ && c >= 0 && c < cols_);
    return data_[static_cast<std::size_t>(r) * cols_ + c];
  }
  /// Returns entry (r, c), zero-based, read-only (bounds asserted in debug builds).
  const T& operator()(int r, int c) const {
    assert(r >= 0 && r < rows_ && c >= 0 && c < cols_);
    return data_[static_cast<std::size_t>(r) * cols_ + c];
  }
  /// Returns the block of `n` × `n` entries starting at (first, first).
  [[nodiscard]] DenseMatrix block(int first, int n) const {
    DenseMatrix b(n, n);
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c) b(r, c) = (*this)(first + r, first + c);
    return b;
  }

 private:
  int rows_ = 0;
  int cols_ = 0;
  std::vector<T> data_;
};

}  // namespace gkt
