// Checkpoints (experiments/scene/checkpoint_file.hpp, xpbd/state_archive.hpp): state written and
// read back changes no bit, and a checkpoint of another version or scene, or cut short, or
// with a changed byte, is refused saying which. That a resumed run ends with the bytes of a
// run never stopped is tested end to end by run_resume.sh.
#include "experiments/scene/checkpoint_file.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "xpbd/state_archive.hpp"
#include "xpbd/types.hpp"

namespace rice::experiments {
namespace {

struct Plain {
  std::array<int, 4> key{1, 2, 3, 4};
  xpbd::Vec3 anchor{0.1, -0.2, 0.3};
  bool sliding = true;
};

TEST(StateArchive, WhatIsWrittenIsReadBackBitForBit) {
  xpbd::Positions x(3, 3);
  x << 1, 2, 3, 4, 5, 6, 7, 8, 0.1;
  std::vector<Plain> plain(2);
  plain[1].anchor.x() = -0.0;
  const std::map<std::pair<int, int>, double> broken = {{{1, 2}, 0.5}, {{0, 7}, 1e-300}};
  const std::vector<std::vector<std::string>> rows = {{"1", "a"}, {}, {"x"}};
  const std::optional<double> some = 2.5, none;
  xpbd::StateWriter out;
  out(x, plain, broken, rows, some, none, std::string("rng"), 42L);

  xpbd::Positions x2;
  std::vector<Plain> plain2;
  std::map<std::pair<int, int>, double> broken2;
  std::vector<std::vector<std::string>> rows2;
  std::optional<double> some2, none2 = 1.0;
  std::string text;
  long n = 0;
  xpbd::StateReader in(out.bytes());
  in(x2, plain2, broken2, rows2, some2, none2, text, n);
  EXPECT_TRUE(in.at_end());
  EXPECT_EQ(x2, x);
  ASSERT_EQ(plain2.size(), 2u);
  EXPECT_EQ(plain2[1].key, plain[1].key);
  EXPECT_TRUE(std::signbit(plain2[1].anchor.x()));
  EXPECT_EQ(broken2, broken);
  EXPECT_EQ(rows2, rows);
  EXPECT_EQ(some2, some);
  EXPECT_FALSE(none2.has_value());
  EXPECT_EQ(text, "rng");
  EXPECT_EQ(n, 42);
}

// A rigid scene's model has no vertices: empty matrices and vectors, whose data() is null,
// must pass through (the sanitizers flagged memcpy from a null pointer before).
TEST(StateArchive, EmptyMatricesAndVectorsAreReadBackEmpty) {
  xpbd::StateWriter out;
  out(xpbd::Positions(0, 3), std::vector<Plain>{}, std::vector<double>{});
  xpbd::Positions x(2, 3);
  std::vector<Plain> plain(1);
  std::vector<double> values(4);
  xpbd::StateReader in(out.bytes());
  in(x, plain, values);
  EXPECT_TRUE(in.at_end());
  EXPECT_EQ(x.rows(), 0);
  EXPECT_TRUE(plain.empty());
  EXPECT_TRUE(values.empty());
}

TEST(StateArchive, BytesThatEndEarlyOrClaimTooMuchAreRefused) {
  xpbd::StateWriter out;
  out(std::vector<double>{1.0, 2.0, 3.0});
  const std::string bytes = out.bytes();
  std::vector<double> v;
  xpbd::StateReader cut(std::string_view(bytes).substr(0, bytes.size() - 1));
  EXPECT_THROW(cut(v), std::runtime_error);
  std::string huge = bytes;
  huge[7] = '\x7f';  // a size of about 2^63 elements
  xpbd::StateReader claims(huge);
  EXPECT_THROW(claims(v), std::runtime_error);
}

TEST(CheckpointFile, IsReadBackAndRefusedNamingWhy) {
  const Checkpoint written{0x1234, 17, std::string("state \0 bytes", 13)};
  const std::string bytes = checkpoint_bytes(written);
  const Checkpoint read = parse_checkpoint(bytes, 0x1234, "run/checkpoint.bin");
  EXPECT_EQ(read.frame, 17);
  EXPECT_EQ(read.state, written.state);

  const auto refusal = [&](std::string_view file, std::uint64_t digest) {
    try {
      parse_checkpoint(file, digest, "run/checkpoint.bin");
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(refusal(bytes, 0x9999).find("from another scene"), std::string::npos);
  EXPECT_NE(refusal(std::string_view(bytes).substr(0, bytes.size() - 3), 0x1234).find("truncated"), std::string::npos);
  EXPECT_NE(refusal(std::string_view(bytes).substr(0, 20), 0x1234).find("truncated"), std::string::npos);
  std::string version = bytes;
  version[16] = 9;  // the version's low byte
  EXPECT_NE(refusal(version, 0x1234).find("checkpoint version 9"), std::string::npos);
  std::string flipped = bytes;
  flipped.back() ^= 1;
  EXPECT_NE(refusal(flipped, 0x1234).find("corrupted"), std::string::npos);
  EXPECT_NE(refusal("rice frames\n", 0x1234).find("not a rice checkpoint"), std::string::npos);
  EXPECT_EQ(refusal(bytes, 0x9999).rfind("run/checkpoint.bin: ", 0), 0u);
}

}  // namespace
}  // namespace rice::experiments
