// Output files are written atomically: new content replaces old whole, nothing else is left
// in the folder, a folder being prepared loses the temporaries of killed runs, and a failure
// names the path.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "experiments/io/atomic_file.hpp"
#include "experiments/io/png_image.hpp"

namespace rice::experiments {
namespace {

namespace fs = std::filesystem;

std::string bytes_of(const fs::path& path) {
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
  EXPECT_EQ(bytes_of(folder / "table.csv"), "a,b\n3,4\n5,6\n");
  EXPECT_EQ(bytes_of(folder / "mesh.txt"), "streamed\n");
  EXPECT_TRUE(bytes_of(folder / "image.png").starts_with("\x89PNG"));
  int files = 0;
  for (const auto& entry : fs::directory_iterator(folder)) {
    ++files;
    EXPECT_TRUE(entry.is_regular_file()) << entry.path();
    EXPECT_EQ((fs::status(entry.path()).permissions() & fs::perms::owner_read), fs::perms::owner_read);
  }
  EXPECT_EQ(files, 3) << "a temporary was left behind";
  fs::remove_all(folder);
}

// The pid of a process that has ended (and been reaped).
pid_t ended_process() {
  const pid_t pid = ::fork();
  if (pid == 0) ::_exit(0);
  ::waitpid(pid, nullptr, 0);
  return pid;
}

TEST(Output, PreparingAFolderRemovesTemporariesOfKilledRunsOnly) {
  const fs::path folder = fs::temp_directory_path() / ("rice-stale-" + std::to_string(::getpid()));
  fs::remove_all(folder);
  fs::create_directories(folder);
  const std::string dead = ".table.csv.partial-" + std::to_string(ended_process()) + "-3";
  const std::string live = ".table.csv.partial-" + std::to_string(::getppid()) + "-0";
  for (const std::string& name : {dead, live, std::string(".notes.partial"), std::string("table.csv")})
    std::ofstream(folder / name) << "x";
  make_output_folder(folder);
  EXPECT_FALSE(fs::exists(folder / dead)) << "a killed run's temporary was kept";
  EXPECT_TRUE(fs::exists(folder / live)) << "a running process's temporary was removed";
  EXPECT_TRUE(fs::exists(folder / ".notes.partial"));
  EXPECT_TRUE(fs::exists(folder / "table.csv"));
  fs::remove_all(folder);
}

TEST(Output, AnImageLibpngRefusesIsAnErrorNotACrash) {
  EXPECT_THROW(encode_png(RgbImage(0, 2)), std::runtime_error);  // libpng: width is zero
  EXPECT_TRUE(encode_png(RgbImage(1, 1)).starts_with("\x89PNG")) << "the failure left libpng unusable";
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
