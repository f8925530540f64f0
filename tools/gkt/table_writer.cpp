#include "table_writer.hpp"

#include <cerrno>
#include <charconv>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <stdexcept>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

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

std::string quote_short(const std::string& text) {
  constexpr std::size_t kMaxEcho = 40;
  if (text.size() <= kMaxEcho) return text;
  std::size_t cut = kMaxEcho;
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;  // not inside a UTF-8 character
  return text.substr(0, cut) + "…";
}

std::string csv_line(const std::vector<std::string>& cells) {
  std::string out;
  for (std::size_t c = 0; c < cells.size(); ++c) {
    if (c > 0) out += ',';
    out += cells[c];
  }
  out += '\n';
  return out;
}

std::string csv_interrupted_line(const Table& t) {
  return "# interrupted after " + std::to_string(t.rows.size()) + " of " + std::to_string(t.planned_rows) + " rows\n";
}

std::string to_csv(const Table& t) {
  std::string out = csv_line(t.columns);
  for (const auto& row : t.rows) out += csv_line(row);
  if (t.interrupted) out += csv_interrupted_line(t);
  return out;
}

std::string to_json(const Table& t) {
  nlohmann::ordered_json doc;
  doc["model"] = t.model;
  doc["gkt_version"] = GKT_VERSION;  // every JSON output says which gkt wrote it (issue 19)
  const auto description =
      t.description_json.empty() ? nlohmann::ordered_json::object() : nlohmann::ordered_json::parse(t.description_json);
  for (const auto& [key, value] : description.items())
    if (key != "column_descriptions") doc[key] = value;
  doc["columns"] = t.columns;
  if (description.contains("column_descriptions")) doc["column_descriptions"] = description["column_descriptions"];
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
  if (t.interrupted) {
    doc["interrupted"] = true;
    doc["planned_rows"] = t.planned_rows;
  }
  return doc.dump(2) + "\n";
}

namespace {

std::invalid_argument output_error(const std::string& path, const std::string& what) {
  return std::invalid_argument(path + ": " + what);
}

std::string reason(int error_number) { return std::strerror(error_number); }

/// The temporary file of the running command, removed if SIGINT, SIGTERM or SIGHUP ends it (the
/// handler may only use async-signal-safe calls: unlink on a fixed buffer, then the default action).
char pending_temporary[4096];
volatile std::sig_atomic_t pending = 0;

extern "C" void remove_pending_temporary(int signal_number) {
  if (pending != 0) ::unlink(pending_temporary);
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
}

void guard_temporary(const std::string& path) {
  if (path.size() >= sizeof pending_temporary) return;  // cannot happen within PATH_MAX; then unguarded
  std::memcpy(pending_temporary, path.c_str(), path.size() + 1);
  pending = 1;
  for (int signal_number : {SIGINT, SIGTERM, SIGHUP}) std::signal(signal_number, remove_pending_temporary);
}

void release_temporary() { pending = 0; }

/// Writes all of `content` to `descriptor`; returns 0 or the errno of the failure.
int write_all(int descriptor, const std::string& content) {
  std::size_t done = 0;
  while (done < content.size()) {
    const ssize_t n = ::write(descriptor, content.data() + done, content.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return n < 0 ? errno : EIO;
    done += static_cast<std::size_t>(n);
  }
  return 0;
}

}  // namespace

OutputTarget::OutputTarget(std::string path) : path_(std::move(path)) {
  if (path_.empty()) return;  // standard output: checked when written
  namespace fs = std::filesystem;
  const fs::path target(path_);
  struct stat st {};
  if (::lstat(path_.c_str(), &st) == 0) {
    if (S_ISLNK(st.st_mode)) {
      struct stat pointed {};
      if (::stat(path_.c_str(), &pointed) != 0 || !(S_ISFIFO(pointed.st_mode) || S_ISCHR(pointed.st_mode)))
        throw output_error(path_,
                           "is a symbolic link; give the path of the file it points to (gkt replaces regular "
                           "files only, never a link)");
      st = pointed;  // e.g. /dev/stdout on a pipe or a terminal: written through the link
    }
    if (S_ISDIR(st.st_mode)) throw output_error(path_, "is a directory; give a file name");
    if (S_ISFIFO(st.st_mode) || S_ISCHR(st.st_mode)) {
      if (::access(path_.c_str(), W_OK) != 0) throw output_error(path_, "not writable (" + reason(errno) + ")");
      kind_ = Kind::direct;
      return;
    }
    if (!S_ISREG(st.st_mode))
      throw output_error(path_,
                         "is a block device or a socket; gkt writes regular files, FIFOs and character devices only");
    mode_ = st.st_mode & 07777;
    owner_ = st.st_uid;
    group_ = st.st_gid;
  } else {
    const int lstat_error = errno;
    if (lstat_error == ENOTDIR) throw output_error(path_, "'" + target.parent_path().string() + "' is not a folder");
    if (lstat_error != ENOENT) throw output_error(path_, "cannot write here (" + reason(lstat_error) + ")");
    if (!target.has_filename()) throw output_error(path_, "names a folder that does not exist; give a file name");
    const std::string folder = target.has_parent_path() ? target.parent_path().string() : ".";
    struct stat folder_status {};
    if (::stat(folder.c_str(), &folder_status) != 0)
      throw output_error(path_, "folder '" + folder + "' does not exist");
    if (!S_ISDIR(folder_status.st_mode)) throw output_error(path_, "'" + folder + "' is not a folder");
    const mode_t mask = ::umask(0);
    ::umask(mask);
    mode_ = 0666 & ~mask;
  }
  kind_ = Kind::replace;
  const std::string folder = target.has_parent_path() ? target.parent_path().string() : ".";
  std::string name = target.filename().string();  // insert/append, not "." + name: GCC 12's -Wrestrict misfires
  name.insert(0, 1, '.');
  name.append(".gkt-XXXXXX");
  std::string pattern = (target.parent_path() / name).string();
  descriptor_ = ::mkstemp(pattern.data());
  if (descriptor_ < 0)
    throw output_error(path_, "cannot create a file in folder '" + folder + "' (" + reason(errno) + ")");
  temporary_ = pattern;
  guard_temporary(temporary_);
}

OutputTarget::~OutputTarget() {
  if (descriptor_ >= 0) ::close(descriptor_);
  if (!temporary_.empty()) ::unlink(temporary_.c_str());
  release_temporary();
}

void OutputTarget::write(const std::string& content) {
  append(content);
  commit();
}

void OutputTarget::append(const std::string& chunk) {
  switch (kind_) {
    case Kind::standard_output: {
      std::cout.flush();
      errno = 0;
      const std::size_t written = std::fwrite(chunk.data(), 1, chunk.size(), stdout);
      const bool failed = written != chunk.size() || std::fflush(stdout) != 0 || std::ferror(stdout) != 0;
      if (failed) throw output_error("standard output", "write failed (" + reason(errno != 0 ? errno : EIO) + ")");
      return;
    }
    case Kind::direct: {
      if (descriptor_ < 0) {
        descriptor_ = ::open(path_.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
        if (descriptor_ < 0) throw output_error(path_, "cannot open for writing (" + reason(errno) + ")");
      }
      const int failure = write_all(descriptor_, chunk);
      if (failure != 0) {
        ::close(descriptor_);
        descriptor_ = -1;
        throw output_error(path_, "write failed (" + reason(failure) + ")");
      }
      return;
    }
    case Kind::replace: {
      const int failure = descriptor_ < 0 ? EBADF : write_all(descriptor_, chunk);
      if (failure != 0) throw output_error(path_, "write failed (" + reason(failure) + "); nothing was written");
      return;  // ~OutputTarget removes the temporary file unless commit() renamed it
    }
  }
}

void OutputTarget::commit() {
  switch (kind_) {
    case Kind::standard_output:
      append("");
      return;
    case Kind::direct: {
      if (descriptor_ < 0) append("");  // opens: an empty output still reaches the FIFO or device
      const int closed = ::close(descriptor_) == 0 ? 0 : errno;
      descriptor_ = -1;
      if (closed != 0) throw output_error(path_, "write failed (" + reason(closed) + ")");
      return;
    }
    case Kind::replace: {
      int failure = descriptor_ < 0 ? EBADF : 0;
      if (failure == 0 && owner_ >= 0 && ::geteuid() == 0)  // root replacing a user's file keeps its owner
        static_cast<void>(::fchown(descriptor_, static_cast<uid_t>(owner_), static_cast<gid_t>(group_)));
      if (failure == 0 && ::fchmod(descriptor_, static_cast<mode_t>(mode_)) != 0) failure = errno;
      if (failure == 0 && ::fsync(descriptor_) != 0 && errno != EINVAL) failure = errno;
      const int closed = descriptor_ < 0 || ::close(descriptor_) == 0 ? 0 : errno;
      descriptor_ = -1;
      if (failure == 0) failure = closed;
      if (failure != 0) throw output_error(path_, "write failed (" + reason(failure) + "); nothing was written");
      if (::rename(temporary_.c_str(), path_.c_str()) != 0)
        throw output_error(path_, "cannot replace (" + reason(errno) + "); nothing was written");
      release_temporary();
      temporary_.clear();
      return;
    }
  }
}

}  // namespace gkt::cli
