// checkpoint.bin: what is written is read back bit for bit, files of the previous format are
// still read, and damage anywhere (including the integrator state) is refused by name.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "biphasic/io/checkpoint.hpp"

namespace fs = std::filesystem;
using biphasic::Checkpoint;
using biphasic::CheckpointError;

namespace {

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("biphasic_test_checkpoint_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const fs::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary) << bytes;
}

Checkpoint sample() {
  Checkpoint c;
  c.case_hash = 0x1234'5678'9abc'def0ULL;
  c.step = 7;
  c.t = 3.5;
  c.last_dt = 0.5;
  c.y = {1.0, -2.5e-3, 0.1 + 0.2, 4e-300};
  c.ydot = {0.0, 1.0 / 3.0, -7.0, 1e300};
  c.record = R"({"steps":[1,2,3]})";
  c.integrator_state = {1.0, 0.0, 2.0, 0.0, 0.25, 1.0, 3.25, 0.25, 9.0, 8.0};
  return c;
}

/// A version-1 file of `c` (no integrator state), laid out by hand as that format defined it.
std::string version1_bytes(const Checkpoint& c) {
  std::string out(16, '\0');
  std::memcpy(out.data(), "BIPHASIC-CKPT", 13);
  auto put = [&out](const auto& v) { out.append(reinterpret_cast<const char*>(&v), sizeof v); };
  put(std::uint32_t{1});
  put(std::uint32_t{0});
  put(c.case_hash);
  put(static_cast<std::uint64_t>(c.y.size()));
  put(c.step);
  put(c.t);
  put(c.last_dt);
  put(static_cast<std::uint64_t>(c.record.size()));
  for (double v : c.y) put(v);
  for (double v : c.ydot) put(v);
  out += c.record;
  put(biphasic::fnv1a64(out));
  return out;
}

}  // namespace

TEST(Checkpoint, RoundTripsEveryFieldBitForBit) {
  const fs::path p = scratch("roundtrip") / "checkpoint.bin";
  const Checkpoint c = sample();
  biphasic::write_checkpoint(p.string(), c);
  const Checkpoint r = biphasic::read_checkpoint(p.string());
  EXPECT_EQ(r.case_hash, c.case_hash);
  EXPECT_EQ(r.step, c.step);
  EXPECT_EQ(r.t, c.t);
  EXPECT_EQ(r.last_dt, c.last_dt);
  EXPECT_EQ(r.y, c.y);
  EXPECT_EQ(r.ydot, c.ydot);
  EXPECT_EQ(r.record, c.record);
  EXPECT_EQ(r.integrator_state, c.integrator_state);
}

TEST(Checkpoint, ReadsTheFirstFormatWithoutIntegratorState) {
  const fs::path p = scratch("v1") / "checkpoint.bin";
  const Checkpoint c = sample();
  write_bytes(p, version1_bytes(c));
  const Checkpoint r = biphasic::read_checkpoint(p.string());
  EXPECT_EQ(r.y, c.y);
  EXPECT_EQ(r.ydot, c.ydot);
  EXPECT_EQ(r.record, c.record);
  EXPECT_TRUE(r.integrator_state.empty());
}

TEST(Checkpoint, RefusesDamageInEveryPart) {
  const fs::path dir = scratch("damaged");
  const fs::path good = dir / "good.bin";
  biphasic::write_checkpoint(good.string(), sample());
  const std::string bytes = read_bytes(good);
  const fs::path p = dir / "checkpoint.bin";
  auto message_for = [&](const std::string& damaged) -> std::string {
    write_bytes(p, damaged);
    try {
      biphasic::read_checkpoint(p.string());
    } catch (const CheckpointError& e) {
      return e.what();
    }
    return "accepted";
  };
  // Offsets in the version-2 layout: 16 bytes of magic, the version word pair, seven 8-byte
  // header fields (the state length last, at 72), then y and ẏ (4 values each), then the state.
  const std::size_t state_length_at = 72;
  const std::size_t state_at = state_length_at + 8 + 2 * 4 * 8;
  EXPECT_NE(message_for(bytes.substr(0, state_at + 12)).find("truncated in the integrator state"),
            std::string::npos);
  // One flipped bit in the integrator state: the checksum catches it.
  std::string flipped = bytes;
  flipped[state_at + 20] ^= 0x10;
  EXPECT_NE(message_for(flipped).find("checksum mismatch"), std::string::npos);
  // A state length larger than the file.
  std::string huge = bytes;
  const std::uint64_t big = 1ULL << 60;
  std::memcpy(huge.data() + state_length_at, &big, sizeof big);
  EXPECT_NE(message_for(huge).find("integrator state of"), std::string::npos);
  // A future format version.
  std::string future = bytes;
  const std::uint32_t v = Checkpoint::kFormatVersion + 1;
  std::memcpy(future.data() + 16, &v, sizeof v);
  EXPECT_NE(message_for(future).find("format version"), std::string::npos);
}
