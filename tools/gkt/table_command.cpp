#include "table_command.hpp"

#include <algorithm>
#include <atomic>
#include <charconv>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <exception>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>
#include <utility>

#include "gkt/algebra/thread_caches.hpp"
#include "gkt/models/tolerance_row.hpp"

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

/// One finished row: its cells and what the in-order bookkeeping (warnings) needs.
struct RowResult {
  std::vector<std::string> cells;
  std::string tolerance_warning;  ///< empty unless a tolerance was not reached
  int order = 0;
  struct Flag {
    bool unreliable = false;  ///< estimated error above |value|
    double value = 0, error = 0;
  };
  std::vector<Flag> flags;  ///< per coefficient
  std::exception_ptr failure;
};

/// Returns the axis indices of row `r` (last axis fastest).
std::vector<std::size_t> row_index(const Scene& scene, std::size_t r) {
  std::vector<std::size_t> index(scene.axes.size(), 0);
  for (std::size_t a = scene.axes.size(); a > 0;) {
    --a;
    const std::size_t n = scene.axes[a].values.size();
    index[a] = r % n;
    r /= n;
  }
  return index;
}

/// True if the scene scans to a tolerance: its tables carry a `<c>_order` column per coefficient.
bool has_tolerance(const Scene& scene) {
  return std::any_of(scene.axes.begin(), scene.axes.end(), [](const auto& axis) { return axis.key == "tolerance"; });
}

/// Returns row `r` of the sweep evaluated with `model`.
RowResult compute_row(TransportModel& model, const Scene& scene, const TableOptions& options, std::size_t r) {
  const auto index = row_index(scene, r);
  RowResult result;
  ParameterPoint parameters;
  parameters.choices = scene.choices;
  OrderRequest request;
  std::vector<std::string>& row = result.cells;
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
  std::vector<CoefficientValue> values;
  if (request.tolerance) {
    // The library's row (gkt/models/tolerance_row.hpp): each coefficient at the row's order unless its error
    // there misses the tolerance its own scan met; the `<c>_order` columns say which order each value is at.
    const Rational tolerance = *request.tolerance;
    ToleranceRow scanned = evaluate_tolerance_row(model, parameters, scene.coefficients, tolerance);
    values = std::move(scanned.values);
    request.order = scanned.order;
    std::string worst, others, why;
    double worst_error = -1;
    for (std::size_t k = 0; k < values.size(); ++k) {
      if (values[k].converged) continue;
      // Why an estimate is flagged not converging (theory.md (6.1), (6.3)): said per coefficient, since an error
      // below the tolerance is otherwise a puzzle.
      if (values[k].defined && values[k].divergence != Divergence::none)
        why += "; " + scene.coefficients[k] + ": " + describe_divergence(values[k].divergence, values[k].order);
      const double e = values[k].defined ? values[k].error.to_double() : HUGE_VAL;
      if (e > worst_error) {
        if (!worst.empty()) others += (others.empty() ? "" : ", ") + worst;
        worst_error = e;
        worst = scene.coefficients[k];
      } else {
        others += (others.empty() ? "" : ", ") + scene.coefficients[k];
      }
    }
    if (!worst.empty()) {
      std::string at;
      for (std::size_t a = 0; a < scene.axes.size(); ++a)
        if (scene.axes[a].swept && scene.axes[a].key != "tolerance")
          at += scene.axes[a].key + "=" + format_parameter(scene.axes[a].values[index[a]]) + " ";
      result.tolerance_warning = at + "tolerance " + format_error(tolerance.to_double()) +
                                 " not reached: row at order " + std::to_string(scanned.order) +
                                 ", largest estimated error " + format_error(worst_error) + " (" + worst + ")" +
                                 (others.empty() ? "" : "; also above the tolerance: " + others) + why;
    }
  } else {
    values = model.evaluate(parameters, scene.coefficients, request);
  }
  // --units physical: each coefficient (and its error) times the SI value of its reduction at
  // this row's dimension (docs/conventions.md "Physical units").
  std::vector<double> scale(values.size(), 1.0);
  if (options.physical) {
    const auto given = parameters.numbers.find("dimension");
    int dimension = 3;  // a model without the key is three-dimensional (viscoelastic spheres)
    if (given != parameters.numbers.end())
      dimension = static_cast<int>(given->second.to_double());
    else
      for (const auto& spec : model.parameters())
        if (spec.name == "dimension") dimension = static_cast<int>(spec.default_value.to_double());
    for (std::size_t k = 0; k < values.size(); ++k)
      scale[k] =
          physical_scale(describe_column(scene.model, scene.coefficients[k]).reduction, dimension, *options.physical);
  }
  for (std::size_t k = 0; k < values.size(); ++k) {
    const auto& v = values[k];
    if (options.exact && !v.exact)
      throw std::invalid_argument("--exact: a requested coefficient is not a rational number here (model " +
                                  scene.model + "); drop --exact");
    if (!v.defined)
      row.emplace_back("nan");  // no solution at this order
    else if (v.infinite)
      row.emplace_back("inf");  // e.g. critical_length of the elastic gas (JSON: null)
    else
      row.push_back(options.exact ? v.value.to_string() : format_number(v.value.to_double() * scale[k]));
  }
  for (std::size_t k = 0; k < values.size(); ++k) {
    const auto& v = values[k];
    row.push_back(!v.defined ? "inf" : v.error_estimated ? format_error(v.error.to_double() * scale[k]) : "nan");
  }
  if (request.tolerance)
    for (const auto& v : values) row.push_back(std::to_string(v.order));  // the `<c>_order` columns
  result.order = request.tolerance || values.empty() ? request.order : values.front().order;
  row.push_back(std::to_string(result.order));
  for (const auto& v : values) {
    RowResult::Flag flag;
    if (v.defined && v.error_estimated && v.error > v.value.abs()) {
      flag.unreliable = true;
      flag.value = v.value.to_double();
      flag.error = v.error.to_double();
    }
    result.flags.push_back(flag);
  }
  return result;
}

/// The rows of a sweep shared between the workers and the thread that collects them in order.
/// Held by shared pointer: after an interrupt, detached workers may still finish their row.
struct Sweep {
  Sweep(const Scene& s, const TableOptions& o)
      : scene(s), options(o), total(sweep_size(s)), window(4 * static_cast<std::size_t>(std::max(o.jobs, 1))) {}
  const Scene scene;
  const TableOptions options;
  const std::size_t total;
  /// A worker starts row r only when r < collected + window: at most `window` finished rows wait
  /// for a slow earlier one (memory bounded whatever the sweep's length).
  const std::size_t window;
  std::mutex mutex;
  std::condition_variable finished;
  std::condition_variable room;              ///< collected moved on (or the sweep stopped)
  std::map<std::size_t, RowResult> results;  ///< finished, not yet collected rows by index; guarded by mutex
  std::size_t collected = 0;                 ///< rows handed to the writer; guarded by mutex
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};    ///< the collector is done (interrupted, failed or finished): workers leave
  std::atomic<bool> failed{false};  ///< a row failed: workers claim no new row
};

/// Takes the next unclaimed row until none is left or the sweep stops; its own model instance
/// (models cache state, and so never share one between threads).
void work_rows(const std::shared_ptr<Sweep>& sweep) {
  std::unique_ptr<TransportModel> model;
  while (!sweep->stop && !sweep->failed) {
    const std::size_t r = sweep->next.fetch_add(1);
    if (r >= sweep->total) return;
    {
      // A claimed row is computed unless the collector is done (stop): the rows before a failure
      // must all arrive for the collector to reach it.
      std::unique_lock lock(sweep->mutex);
      while (r >= sweep->collected + sweep->window && !sweep->stop)
        sweep->room.wait_for(lock, std::chrono::milliseconds(100));  // timed: stop is not set under the lock
    }
    if (sweep->stop) return;
    RowResult result;
    try {
      if (!model) model = make_transport_model(sweep->scene.model);
      result = compute_row(*model, sweep->scene, sweep->options, r);
    } catch (...) {
      result.failure = std::current_exception();
      sweep->failed = true;  // rows after a failure are not needed: claim no more
    }
    {
      const std::lock_guard lock(sweep->mutex);
      sweep->results.emplace(r, std::move(result));
    }
    sweep->finished.notify_all();
  }
}

/// One worker thread: its rows, then (its model destroyed) its exact-arithmetic caches freed.
void work(const std::shared_ptr<Sweep>& sweep) {
  work_rows(sweep);
  release_thread_arithmetic_caches();
}

/// The worker threads: joined when the sweep ends normally or by an error, detached on interrupt.
class Workers {
 public:
  Workers(const std::shared_ptr<Sweep>& sweep, int jobs) : sweep_(sweep) {
    const std::size_t n =
        std::min<std::size_t>(static_cast<std::size_t>(std::max(jobs, 1)), std::max<std::size_t>(sweep->total, 1));
    for (std::size_t i = 0; i < n; ++i) threads_.emplace_back(work, sweep);
  }
  ~Workers() {
    sweep_->stop = true;
    for (auto& t : threads_)
      if (t.joinable()) t.join();
  }
  Workers(const Workers&) = delete;
  Workers& operator=(const Workers&) = delete;
  void detach() {
    sweep_->stop = true;
    for (auto& t : threads_) t.detach();
  }

 private:
  std::shared_ptr<Sweep> sweep_;
  std::vector<std::thread> threads_;
};

}  // namespace

std::size_t sweep_size(const Scene& scene) {
  std::size_t n = 1;
  for (const auto& axis : scene.axes) n *= axis.values.size();
  return n;
}

Table compute_table(const Scene& scene, const TableOptions& options, std::vector<std::string>& warnings) {
  return compute_table(scene, options, warnings, RowObserver{});
}

Table table_header(const Scene& scene, const TableOptions& options) {
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
  if (has_tolerance(scene))
    for (const auto& c : scene.coefficients) {
      table.columns.push_back(c + "_order");
      table.numeric.push_back(true);
    }
  table.columns.push_back("order");
  table.numeric.push_back(true);
  table.planned_rows = sweep_size(scene);
  return table;
}

Table compute_table(const Scene& scene, const TableOptions& options, std::vector<std::string>& warnings,
                    const RowObserver& observer) {
  Table table = table_header(scene, options);

  // Values whose estimated error exceeds their magnitude: counted per coefficient, the worst
  // (largest error/|value|) kept, one warning line each at the end.
  struct Unreliable {
    std::size_t rows = 0;
    double ratio = -1, value = 0, error = 0;
    std::string where;
  };
  std::vector<Unreliable> unreliable(scene.coefficients.size());

  auto sweep = std::make_shared<Sweep>(scene, options);
  Workers workers(sweep, options.jobs);
  const auto stop_requested = [&observer] { return observer.stop && observer.stop(); };
  for (std::size_t r = 0; r < sweep->total; ++r) {
    std::optional<RowResult> finished;
    {
      std::unique_lock lock(sweep->mutex);
      while (sweep->results.count(r) == 0 && !stop_requested()) {
        sweep->finished.wait_for(lock, std::chrono::milliseconds(100));
        if (sweep->results.count(r) == 0 && observer.on_wait) {
          lock.unlock();
          observer.on_wait(r, sweep->total);
          lock.lock();
        }
      }
      if (auto node = sweep->results.extract(r)) {
        finished = std::move(node.mapped());
        sweep->collected = r + 1;
      }
    }
    sweep->room.notify_all();
    if (!finished) {  // interrupted: the rows finished in order are kept
      table.interrupted = true;
      workers.detach();
      break;
    }
    if (finished->failure) std::rethrow_exception(finished->failure);  // ~Workers joins
    if (!finished->tolerance_warning.empty()) warnings.push_back(std::move(finished->tolerance_warning));
    const auto index = row_index(scene, r);
    for (std::size_t k = 0; k < finished->flags.size(); ++k) {
      const auto& flag = finished->flags[k];
      if (!flag.unreliable) continue;
      auto& u = unreliable[k];
      ++u.rows;
      const double ratio = flag.value == 0 ? HUGE_VAL : flag.error / std::abs(flag.value);
      if (ratio > u.ratio) {
        u.ratio = ratio;
        u.value = flag.value;
        u.error = flag.error;
        u.where.clear();
        for (std::size_t a = 0; a < scene.axes.size(); ++a)
          if (scene.axes[a].swept && scene.axes[a].key != "order")
            u.where += scene.axes[a].key + "=" + format_parameter(scene.axes[a].values[index[a]]) + ", ";
        u.where += "order " + std::to_string(finished->order);
      }
    }
    table.rows.push_back(std::move(finished->cells));
    if (observer.on_row) observer.on_row(table.rows.back(), table.rows.size(), sweep->total);
  }
  // What the error columns do not cover, once per table (docs/conventions.md, "Warnings").
  int highest_order = 0;
  for (const auto& axis : scene.axes)
    if (axis.key == "order")
      for (const auto& v : axis.values) highest_order = std::max(highest_order, static_cast<int>(v.to_double()));
  for (auto& caveat : make_transport_model(scene.model)
                          ->table_caveats(scene.choices, scene.coefficients, highest_order, has_tolerance(scene)))
    warnings.push_back(std::move(caveat));
  const std::size_t row_count = table.rows.size();
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
