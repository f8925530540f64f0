#include "table_command.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>

namespace gkt::cli {

namespace {

std::string format_error(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", x);
  return buffer;
}

std::string format_parameter(const Rational& v) {
  Rational integer_part;
  fmpz_tdiv_q(fmpq_numref(integer_part.raw()), fmpq_numref(v.raw()), fmpq_denref(v.raw()));
  return integer_part == v ? v.to_string() : format_number(v.to_double());
}

}  // namespace

Table compute_table(const Scene& scene, const TableOptions& options, std::vector<std::string>& warnings) {
  auto model = make_transport_model(scene.model);
  Table table;
  table.model = scene.model;
  for (const auto& axis : scene.axes)
    if (axis.swept && axis.key != "order") {  // a swept order is the `order` column itself
      table.columns.push_back(axis.key);
      table.numeric.push_back(!options.exact);
    }
  for (const auto& c : scene.coefficients) {
    table.columns.push_back(c);
    table.numeric.push_back(!options.exact);
  }
  for (const auto& c : scene.coefficients) {
    table.columns.push_back(c + "_error");
    table.numeric.push_back(true);  // an estimate: always a decimal, also under --exact
  }
  table.columns.push_back("order");
  table.numeric.push_back(true);

  // Values whose estimated error exceeds their magnitude: counted per coefficient, the worst
  // (largest error/|value|) kept, one warning line each at the end.
  struct Unreliable {
    std::size_t rows = 0;
    double ratio = -1, value = 0, error = 0;
    std::string where;
  };
  std::vector<Unreliable> unreliable(scene.coefficients.size());
  std::size_t row_count = 0;

  // Cartesian product of the axes, last axis fastest.
  std::vector<std::size_t> index(scene.axes.size(), 0);
  for (bool more = true; more;) {
    ParameterPoint parameters;
    parameters.choices = scene.choices;
    OrderRequest request;
    std::vector<std::string> row;
    for (std::size_t a = 0; a < scene.axes.size(); ++a) {
      const auto& axis = scene.axes[a];
      const Rational& v = axis.values[index[a]];
      if (axis.key == "order")
        request.order = static_cast<int>(fmpz_get_si(fmpq_numref(v.raw())));
      else if (axis.key == "tolerance")
        request.tolerance = v;
      else
        parameters.numbers[axis.key] = v;
      if (axis.swept && axis.key != "order") row.push_back(options.exact ? v.to_string() : format_parameter(v));
    }
    auto values = model->evaluate(parameters, scene.coefficients, request);
    if (request.tolerance) {
      // One order per row: the smallest at which every requested coefficient meets the tolerance.
      int common = 0;
      for (const auto& v : values) common = std::max(common, v.order);
      const Rational tolerance = *request.tolerance;
      request.tolerance.reset();
      request.order = common;
      auto flags = values;
      values = model->evaluate(parameters, scene.coefficients, request);
      for (std::size_t k = 0; k < values.size(); ++k) values[k].converged = flags[k].converged;
      std::string worst;
      double worst_error = -1;
      for (std::size_t k = 0; k < values.size(); ++k)
        if (!values[k].converged && values[k].error.to_double() > worst_error) {
          worst_error = values[k].error.to_double();
          worst = scene.coefficients[k];
        }
      if (!worst.empty()) {
        std::string at;
        for (std::size_t a = 0; a < scene.axes.size(); ++a)
          if (scene.axes[a].swept && scene.axes[a].key != "tolerance")
            at += scene.axes[a].key + "=" + format_parameter(scene.axes[a].values[index[a]]) + " ";
        warnings.push_back(at + "tolerance " + format_error(tolerance.to_double()) + " not reached: row at order " +
                           std::to_string(common) + ", largest estimated error " + format_error(worst_error) + " (" +
                           worst + ")");
      }
    }
    for (const auto& v : values) {
      if (options.exact && !v.exact)
        throw std::invalid_argument("--exact: a requested coefficient is not a rational number here (model " +
                                    scene.model + "); drop --exact");
      if (!v.defined)
        row.emplace_back("nan");  // no solution at this order
      else if (v.infinite)
        row.emplace_back("inf");  // e.g. critical_length of the elastic gas (JSON: null)
      else
        row.push_back(options.exact ? v.value.to_string() : format_number(v.value.to_double()));
    }
    for (const auto& v : values)
      row.push_back(!v.defined ? "inf" : v.error_estimated ? format_error(v.error.to_double()) : "nan");
    const int row_order = values.empty() ? request.order : values.front().order;
    row.push_back(std::to_string(row_order));
    table.rows.push_back(std::move(row));
    ++row_count;
    for (std::size_t k = 0; k < values.size(); ++k) {
      const auto& v = values[k];
      if (!v.defined || !v.error_estimated || !(v.error > v.value.abs())) continue;
      auto& u = unreliable[k];
      ++u.rows;
      const double value = v.value.to_double(), error = v.error.to_double();
      const double ratio = value == 0 ? HUGE_VAL : error / std::abs(value);
      if (ratio > u.ratio) {
        u.ratio = ratio;
        u.value = value;
        u.error = error;
        u.where.clear();
        for (std::size_t a = 0; a < scene.axes.size(); ++a)
          if (scene.axes[a].swept && scene.axes[a].key != "order")
            u.where += scene.axes[a].key + "=" + format_parameter(scene.axes[a].values[index[a]]) + ", ";
        u.where += "order " + std::to_string(row_order);
      }
    }

    more = false;
    for (std::size_t a = scene.axes.size(); a > 0 && !more;) {
      --a;
      more = ++index[a] < scene.axes[a].values.size();
      if (!more) index[a] = 0;
    }
  }
  for (std::size_t k = 0; k < unreliable.size(); ++k) {
    const auto& u = unreliable[k];
    if (u.rows == 0) continue;
    warnings.push_back(scene.coefficients[k] + ": estimated error above the value in " + std::to_string(u.rows) +
                       " of " + std::to_string(row_count) + (row_count == 1 ? " row" : " rows") +
                       " (worst: " + format_error(u.value) + " +- " + format_error(u.error) + " at " + u.where +
                       "); raise the order or read these values as unknown");
  }
  return table;
}

}  // namespace gkt::cli
