// Output files are written atomically: new content replaces old whole, nothing else is left
// in the folder, and a failure names the path.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "experiments/output.hpp"
#include "experiments/png_image.hpp"

namespace rice::experiments {
namespace {

namespace fs = std::filesystem;

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(Output, AtomicWritesReplaceWholeFilesAndLeaveNothingElse) {
  const fs::path folder = fs::temp_directory_path() / ("rice-output-" + std::to_string(::getpid()));
  fs::remove_all(folder);
  make_output_folder(folder);
  write_file_atomically(folder / "table.csv", "a,b\n1,2\n");
  write_file_atomically(folder / "table.csv", "a,b\n3,4\n5,6\n");
  write_file_atomically(folder / "mesh.txt", [](std::ostream& out) { out << "streamed\n"; });
  write_png(folder / "image.png", RgbImage(3, 2));
  EXPECT_EQ(read_bytes(folder / "table.csv"), "a,b\n3,4\n5,6\n");
  EXPECT_EQ(read_bytes(folder / "mesh.txt"), "streamed\n");
  EXPECT_TRUE(read_bytes(folder / "image.png").starts_with("\x89PNG"));
  int files = 0;
  for (const auto& entry : fs::directory_iterator(folder)) {
    ++files;
    EXPECT_TRUE(entry.is_regular_file()) << entry.path();
    EXPECT_EQ((fs::status(entry.path()).permissions() & fs::perms::owner_read), fs::perms::owner_read);
  }
  EXPECT_EQ(files, 3) << "a temporary was left behind";
  fs::remove_all(folder);
}

TEST(Output, AFailedWriteNamesThePath) {
  const fs::path missing = fs::temp_directory_path() / "rice-no-such-folder" / "x.csv";
  try {
    write_file_atomically(missing, "x\n");
    FAIL() << "wrote into a folder that does not exist";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(missing.string()), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace rice::experiments
