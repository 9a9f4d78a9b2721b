#include <gtest/gtest.h>

#include <sstream>
#include <thread>
#include <vector>

#include "sextant/core/error.hpp"
#include "sextant/core/log.hpp"
#include "sextant/core/progress.hpp"

namespace sextant {
namespace {

TEST(Log, LevelsFilterMessages) {
  std::ostringstream sink;
  set_log_sink(&sink);
  const LogLevel before = log_level();
  set_log_level(LogLevel::warning);
  log_info("hidden");
  log_warning("shown");
  log_error("also shown");
  set_log_level(before);
  set_log_sink(nullptr);
  EXPECT_EQ(sink.str(), "[warning] shown\n[error] also shown\n");
  LogLevel level = LogLevel::info;
  EXPECT_TRUE(from_string("warn", &level));
  EXPECT_EQ(level, LogLevel::warning);
  EXPECT_EQ(to_string(LogLevel::warning), "warning") << "the first name is the one written";
  EXPECT_FALSE(from_string("loud", &level));
  EXPECT_THROW(parse_enum(kLogLevelNames, "loud", "--log-level"), InputError);
}

TEST(Progress, CountsTicksFromManyThreads) {
  std::ostringstream sink;
  {
    Progress progress(400, "work", &sink);
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t) {
      threads.emplace_back([&] {
        for (int i = 0; i < 100; ++i) progress.tick();
      });
    }
    for (auto& t : threads) t.join();
    EXPECT_EQ(progress.done(), 400u);
    EXPECT_EQ(progress.eta_seconds(), 0.0);
    progress.finish();
    progress.finish();  // idempotent
  }
  const std::string out = sink.str();
  EXPECT_NE(out.find("work ["), std::string::npos);
  EXPECT_NE(out.find("400/400 100%"), std::string::npos);
  EXPECT_EQ(out.back(), '\n');
  EXPECT_EQ(std::count(out.begin(), out.end(), '\n'), 1);
}

TEST(Progress, QuietWithoutSinkAndEtaUnknownAtStart) {
  Progress progress(10, "quiet", nullptr);
  EXPECT_LT(progress.eta_seconds(), 0.0);
  EXPECT_NE(progress.line().find("ETA ?"), std::string::npos);
  progress.tick(5);
  EXPECT_EQ(progress.done(), 5u);
}

TEST(Progress, DurationFormat) {
  EXPECT_EQ(format_duration(62.0), "1:02");
  EXPECT_EQ(format_duration(3723.0), "1:02:03");
  EXPECT_EQ(format_duration(-1.0), "?");
}

}  // namespace
}  // namespace sextant
