// Progress lines (experiments/io/progress.hpp) into a log, where stderr is not a terminal: a
// line per interval and a last one when the loop is done; a loop shorter than the interval
// writes nothing.
#include "experiments/io/progress.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <string>
#include <thread>

namespace rice::experiments {
namespace {

int lines(const std::string& text) { return static_cast<int>(std::count(text.begin(), text.end(), '\n')); }

TEST(Progress, IntoALogALineEachIntervalAndOneWhenDone) {
  testing::internal::CaptureStderr();  // a file: not a terminal
  Progress every_time("frames", 3, 0.0);
  for (int k = 1; k <= 3; ++k) every_time.update(k);
  every_time.finish();
  const std::string log = testing::internal::GetCapturedStderr();
  EXPECT_EQ(lines(log), 4) << log;
  EXPECT_NE(log.find("frames 2/3, "), std::string::npos) << log;
  EXPECT_NE(log.find("frames done in "), std::string::npos) << log;
  EXPECT_EQ(log.find('\r'), std::string::npos) << "a log has no carriage returns";
}

TEST(Progress, AShortLoopWritesNothingIntoALog) {
  testing::internal::CaptureStderr();
  Progress short_loop("grains", 2);
  short_loop.update(1);
  short_loop.update(2);
  short_loop.finish();
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}

// A resumed run: the time left is paced by the items this process did, not by those done before
// it began (999,000 items "done" in no time would promise the rest in a moment).
TEST(Progress, AResumedLoopIsPacedByTheItemsItDidItself) {
  testing::internal::CaptureStderr();
  Progress resumed("frames", 1'000'000, 0.0, 999'000);
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  resumed.update(999'001);  // 20 ms an item, 999 items left: about 20 s
  const std::string log = testing::internal::GetCapturedStderr();
  const auto at = log.find("frames 999001/1000000, ");
  ASSERT_NE(at, std::string::npos) << log;
  EXPECT_GE(std::stod(log.substr(at + 23)), 19.0) << log;
}

}  // namespace
}  // namespace rice::experiments
