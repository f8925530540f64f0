#include "table_writer.hpp"

#include <charconv>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <system_error>

#include <nlohmann/json.hpp>

namespace gkt::cli {

std::string format_number(double x) {
  char buffer[64];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, x);
  return {buffer, r.ptr};
}

std::string join(const std::vector<std::string>& items, const std::string& quote) {
  std::string out;
  for (const auto& item : items) {
    if (!out.empty()) out += ", ";
    out += quote;
    out += item;
    out += quote;
  }
  return out;
}

std::string to_csv(const Table& t) {
  std::string out;
  auto append_line = [&out](const std::vector<std::string>& cells) {
    for (std::size_t c = 0; c < cells.size(); ++c) {
      if (c > 0) out += ',';
      out += cells[c];
    }
    out += '\n';
  };
  append_line(t.columns);
  for (const auto& row : t.rows) append_line(row);
  return out;
}

std::string to_json(const Table& t) {
  nlohmann::ordered_json doc;
  doc["model"] = t.model;
  doc["columns"] = t.columns;
  auto rows = nlohmann::ordered_json::array();
  for (const auto& row : t.rows) {
    nlohmann::ordered_json r;
    for (std::size_t c = 0; c < row.size(); ++c) {
      if (t.numeric[c] && (row[c] == "nan" || row[c] == "inf"))
        r[t.columns[c]] = nullptr;  // JSON has no NaN/Inf: null means "no value at this order"
      else if (t.numeric[c])
        r[t.columns[c]] = nlohmann::ordered_json::parse(row[c]);
      else
        r[t.columns[c]] = row[c];
    }
    rows.push_back(std::move(r));
  }
  doc["rows"] = std::move(rows);
  return doc.dump(2) + "\n";
}

void write_output(const std::string& path, const std::string& content) {
  if (path.empty()) {
    std::cout << content << std::flush;
    return;
  }
  namespace fs = std::filesystem;
  const fs::path target(path);
  std::string temporary_name = target.filename().string();
  temporary_name.insert(0, 1, '.');
  temporary_name.append(".gkt-tmp");
  const fs::path temporary = target.parent_path() / temporary_name;
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("output: cannot write '" + temporary.string() + "'");
    out << content;
    out.close();
    if (!out) {
      std::error_code ignored;
      fs::remove(temporary, ignored);
      throw std::runtime_error("output: write to '" + temporary.string() + "' failed");
    }
  }
  std::error_code ec;
  fs::rename(temporary, target, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw std::runtime_error("output: cannot rename to '" + path + "': " + ec.message());
  }
}

}  // namespace gkt::cli
