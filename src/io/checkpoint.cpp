#include "biphasic/io/checkpoint.hpp"

#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

#include "biphasic/io/atomic_file.hpp"

namespace biphasic {

namespace {

constexpr char kMagic[16] = "BIPHASIC-CKPT";

template <class T>
void put(std::string& out, const T& value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

/// Reads fixed-size fields from a byte string, failing on truncation.
class Reader {
 public:
  Reader(const std::string& bytes, const std::string& path) : bytes_(bytes), path_(path) {}
  template <class T>
  T get(const char* what) {
    T value;
    need(sizeof value, what);
    std::memcpy(&value, bytes_.data() + pos_, sizeof value);
    pos_ += sizeof value;
    return value;
  }
  void doubles(std::vector<double>& out, std::size_t n, const char* what) {
    need(n * sizeof(double), what);
    out.resize(n);
    if (n > 0)
      std::memcpy(out.data(), bytes_.data() + pos_, n * sizeof(double));  // data() may be null
    pos_ += n * sizeof(double);
  }
  std::string text(std::size_t n, const char* what) {
    need(n, what);
    std::string s = bytes_.substr(pos_, n);
    pos_ += n;
    return s;
  }
  std::size_t pos() const { return pos_; }

 private:
  void need(std::size_t n, const char* what) const {
    if (bytes_.size() - pos_ < n) {
      throw CheckpointError("checkpoint " + path_ + " is damaged: truncated in the " +
                            std::string(what) + " (" + std::to_string(bytes_.size()) + " bytes)");
    }
  }
  const std::string& bytes_;
  const std::string& path_;
  std::size_t pos_ = 0;
};

}  // namespace

std::uint64_t fnv1a64(std::string_view bytes, std::uint64_t seed) {
  std::uint64_t h = seed;
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 1099511628211ULL;
  }
  return h;
}

void write_checkpoint(const std::string& path, const Checkpoint& c) {
  if (c.ydot.size() != c.y.size())
    throw std::logic_error("write_checkpoint: y and ydot differ in size");
  std::string out;
  out.reserve(104 + 16 * c.y.size() + 8 * c.integrator_state.size() + c.record.size());
  out.append(kMagic, sizeof kMagic);
  put(out, Checkpoint::kFormatVersion);
  put(out, std::uint32_t{0});
  put(out, c.case_hash);
  put(out, static_cast<std::uint64_t>(c.y.size()));
  put(out, c.step);
  put(out, c.t);
  put(out, c.last_dt);
  put(out, static_cast<std::uint64_t>(c.record.size()));
  put(out, static_cast<std::uint64_t>(c.integrator_state.size()));
  out.append(reinterpret_cast<const char*>(c.y.data()), c.y.size() * sizeof(double));
  out.append(reinterpret_cast<const char*>(c.ydot.data()), c.ydot.size() * sizeof(double));
  out.append(reinterpret_cast<const char*>(c.integrator_state.data()),
             c.integrator_state.size() * sizeof(double));
  out += c.record;
  put(out, fnv1a64(out));
  write_file_atomically(path, out);
}

Checkpoint read_checkpoint(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw CheckpointError("no checkpoint " + path + " (cannot open it)");
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  Reader r(bytes, path);
  const std::string magic = r.text(sizeof kMagic, "header");
  if (std::memcmp(magic.data(), kMagic, sizeof kMagic) != 0)
    throw CheckpointError("checkpoint " + path + " is damaged or not a checkpoint (bad header)");
  const auto version = r.get<std::uint32_t>("header");
  if (version != 1 && version != Checkpoint::kFormatVersion) {
    throw CheckpointError("checkpoint " + path + " has format version " + std::to_string(version) +
                          "; this build reads versions 1 to " +
                          std::to_string(Checkpoint::kFormatVersion));
  }
  r.get<std::uint32_t>("header");
  Checkpoint c;
  c.case_hash = r.get<std::uint64_t>("header");
  const auto n = r.get<std::uint64_t>("header");
  c.step = r.get<std::int64_t>("header");
  c.t = r.get<double>("header");
  c.last_dt = r.get<double>("header");
  const auto record_size = r.get<std::uint64_t>("header");
  const auto state_size = version >= 2 ? r.get<std::uint64_t>("header") : std::uint64_t{0};
  if (n > bytes.size() / 16 || record_size > bytes.size() || state_size > bytes.size() / 8) {
    throw CheckpointError("checkpoint " + path + " is damaged: header gives " + std::to_string(n) +
                          " unknowns, an integrator state of " + std::to_string(state_size) +
                          " values and a record of " + std::to_string(record_size) +
                          " bytes in a file of " + std::to_string(bytes.size()) + " bytes");
  }
  r.doubles(c.y, n, "state y");
  r.doubles(c.ydot, n, "rate ydot");
  r.doubles(c.integrator_state, state_size, "integrator state");
  c.record = r.text(record_size, "record");
  const std::size_t body = r.pos();
  const auto checksum = r.get<std::uint64_t>("checksum");
  if (checksum != fnv1a64(std::string_view(bytes).substr(0, body)))
    throw CheckpointError("checkpoint " + path + " is damaged: checksum mismatch");
  if (r.pos() != bytes.size())
    throw CheckpointError("checkpoint " + path + " is damaged: bytes after the checksum");
  return c;
}

std::size_t keep_csv_rows_until(const std::string& path, double t_last) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::string line, kept;
  std::size_t rows = 0;
  bool header = true;
  while (std::getline(in, line)) {
    if (header) {
      kept += line + '\n';
      header = false;
      continue;
    }
    // A last line without its newline was cut short by a crash: it is after the checkpoint.
    if (in.eof() || line.empty()) break;
    std::size_t end = 0;
    double t = 0.0;
    try {
      t = std::stod(line.substr(0, line.find(',')), &end);
    } catch (const std::exception&) {
      break;
    }
    if (!(t <= t_last)) break;
    kept += line + '\n';
    ++rows;
  }
  if (in.bad()) throw std::runtime_error("cannot read " + path);
  write_file_atomically(path, kept);
  return rows;
}

}  // namespace biphasic
