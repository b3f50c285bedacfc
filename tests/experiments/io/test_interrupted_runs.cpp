// A long `rice grains --count 60` run killed mid-way with SIGKILL, then interrupted with
// SIGINT (Ctrl-C), leaves only complete, readable files in its output folder (no truncated
// PLY or MEDIT, no partial CSV row, no half-written PNG, no temporary); Ctrl-C ends the run
// with exit code 130 and a message saying where it stopped; a rerun into the same folder
// finishes and writes every file. A run without progress lines names its command instead.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "grains/mesh_io.hpp"

#if !defined(RICE_BINARY) || !defined(RICE_TEST_SCRATCH)
#error "RICE_BINARY and RICE_TEST_SCRATCH must name the rice executable and a scratch folder (tests/CMakeLists.txt)"
#endif

extern char** environ;

namespace rice::experiments {
namespace {

using Clock = std::chrono::steady_clock;
namespace fs = std::filesystem;

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Starts `rice args...` with stdout and stderr into `log`.
pid_t spawn_rice(const std::vector<std::string>& args, const fs::path& log) {
  std::vector<std::string> words = {RICE_BINARY};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  pid_t pid = 0;
  const int error = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  EXPECT_EQ(error, 0) << "cannot start " << RICE_BINARY;
  return pid;
}

int wait_exit(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

// Files in `folder` whose name ends with `suffix`, written after `since`.
int count_files(const fs::path& folder, const std::string& suffix,
                fs::file_time_type since = fs::file_time_type::min()) {
  int count = 0;
  std::error_code error;  // a file may be renamed away while we look
  if (fs::is_directory(folder))
    for (const auto& entry : fs::directory_iterator(folder, error))
      count += entry.path().filename().string().ends_with(suffix) && entry.last_write_time(error) > since ? 1 : 0;
  return count;
}

// Polls until `ready` holds (true) or `limit` passes (false).
template <class Ready>
bool wait_until(Ready ready, std::chrono::seconds limit) {
  const auto end = Clock::now() + limit;
  while (!ready()) {
    if (Clock::now() > end) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return true;
}

// Every line ends in a newline and has as many cells as the header.
void expect_complete_csv(const fs::path& path) {
  const std::string text = read_bytes(path);
  ASSERT_FALSE(text.empty()) << path;
  EXPECT_EQ(text.back(), '\n') << path << " ends inside a row";
  std::istringstream lines(text);
  std::string header, line;
  std::getline(lines, header);
  const auto cells = [](const std::string& row) { return std::count(row.begin(), row.end(), ',') + 1; };
  for (int number = 2; std::getline(lines, line); ++number)
    EXPECT_EQ(cells(line), cells(header)) << path << ":" << number << " is a partial row";
}

void expect_complete_png(const fs::path& path) {
  const std::string bytes = read_bytes(path);
  const std::string signature = "\x89PNG\r\n\x1a\n";
  const std::string iend("\0\0\0\0IEND\xae\x42\x60\x82", 12);  // the last chunk, with its CRC
  EXPECT_TRUE(bytes.starts_with(signature) && bytes.ends_with(iend)) << path << " is not a complete PNG";
}

// Every file in `folder` is complete and readable; nothing else is there.
void expect_only_complete_files(const fs::path& folder) {
  for (const auto& entry : fs::directory_iterator(folder)) {
    const fs::path& path = entry.path();
    const std::string name = path.filename().string();
    SCOPED_TRACE(name);
    if (name.ends_with(".ply")) {
      EXPECT_NO_THROW(grains::read_surface_mesh(path));
    } else if (name.ends_with(".mesh")) {
      EXPECT_NO_THROW(grains::read_medit(path));
    } else if (name.ends_with(".csv")) {
      expect_complete_csv(path);
    } else if (name.ends_with(".png")) {
      expect_complete_png(path);
    } else if (name == "run_info.txt") {
      EXPECT_NE(read_bytes(path).find("\nwall_s: "), std::string::npos) << "run_info.txt is incomplete";
    } else {
      ADD_FAILURE() << "unexpected file " << path << " (a temporary left behind?)";
    }
  }
}

TEST(InterruptedRuns, KilledOrInterruptedGrainRunsLeaveOnlyCompleteFilesAndRerunsFinish) {
  const fs::path scratch = fs::path(RICE_TEST_SCRATCH) / "interrupted-grains";
  const fs::path folder = scratch / "out", log = scratch / "rice.log";
  fs::remove_all(scratch);
  fs::create_directories(scratch);
  // Voxels twice the default size make each grain ~5x cheaper and change no file format.
  const std::vector<std::string> run = {"--threads", "2",        "grains", "--count", "60", "--voxel-size",
                                        "1e-4",      "--out",    folder.string()};

  // SIGKILL once a dozen grains are written: no handler runs, nothing is cleaned up.
  pid_t pid = spawn_rice(run, log);
  ASSERT_TRUE(wait_until([&] { return count_files(folder, ".ply") >= 12; }, std::chrono::seconds(300)))
      << read_bytes(log);
  kill(pid, SIGKILL);
  EXPECT_EQ(wait_exit(pid), 128 + SIGKILL);
  const auto killed_at = fs::file_time_type::clock::now();
  EXPECT_LT(count_files(folder, ".ply"), 60) << "the run ended before it was killed";
  expect_only_complete_files(folder);

  // SIGINT once the rerun into the same folder has rewritten a few grains.
  pid = spawn_rice(run, log);
  ASSERT_TRUE(wait_until([&] { return count_files(folder, ".ply", killed_at) >= 4; }, std::chrono::seconds(300)))
      << read_bytes(log);
  const auto interrupted_at = Clock::now();
  kill(pid, SIGINT);
  EXPECT_EQ(wait_exit(pid), 130) << read_bytes(log);
  const double stop_seconds = std::chrono::duration<double>(Clock::now() - interrupted_at).count();
  std::printf("SIGINT to exit: %.3f s\n", stop_seconds);
  EXPECT_LT(stop_seconds, 10.0) << "a hang guard; the latency itself is reported above";
  const std::string message = read_bytes(log);
  EXPECT_NE(message.find("interrupted by SIGINT during grains "), std::string::npos) << message;
  EXPECT_NE(message.find("/60 done"), std::string::npos) << message;
  expect_only_complete_files(folder);

  // A rerun into the same folder completes.
  pid = spawn_rice(run, log);
  EXPECT_EQ(wait_exit(pid), 0) << read_bytes(log);
  expect_only_complete_files(folder);
  EXPECT_EQ(count_files(folder, ".ply"), 60);
  EXPECT_EQ(count_files(folder, ".mesh"), 60);
  EXPECT_EQ(count_files(folder, "_section.png"), 60);
  std::ifstream table(folder / "grains.csv");
  EXPECT_EQ(std::count(std::istreambuf_iterator<char>(table), std::istreambuf_iterator<char>(), '\n'), 61);
  fs::remove_all(scratch);
}

// A run that reports no progress (the oscillator study has stop points but no item loop)
// names its command when interrupted.
TEST(InterruptedRuns, ARunWithoutProgressNamesItsCommand) {
  const fs::path scratch = fs::path(RICE_TEST_SCRATCH) / "interrupted-oscillator";
  const fs::path folder = scratch / "out", log = scratch / "rice.log";
  fs::remove_all(scratch);
  fs::create_directories(scratch);
  // 10000 substeps a frame: seconds of stepping after the output folder appears.
  const pid_t pid = spawn_rice({"study", "oscillator", "--substeps", "10000", "--out", folder.string()}, log);
  ASSERT_TRUE(wait_until([&] { return fs::is_directory(folder); }, std::chrono::seconds(60))) << read_bytes(log);
  kill(pid, SIGINT);
  EXPECT_EQ(wait_exit(pid), 130) << read_bytes(log);
  const std::string message = read_bytes(log);
  EXPECT_NE(message.find("interrupted by SIGINT during study oscillator;"), std::string::npos) << message;
  fs::remove_all(scratch);
}

}  // namespace
}  // namespace rice::experiments
