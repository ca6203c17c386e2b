// A program parksim starts and talks to: lines both ways, deadlines, a bounded standard error,
// no SIGPIPE, and no process of its group (or zombie) left behind.

#include "parksim/core/system/ChildProcess.h"

#include <signal.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <string>

#include "parksim/core/io/Error.h"

namespace parksim {
namespace {

using Clock = ChildProcess::Clock;

Clock::time_point in(double seconds) {
  return Clock::now() +
         std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
}

ChildProcessDef talking(std::vector<std::string> argv) { return {std::move(argv), true, true}; }

// Orphans of the test's children come to it, so that the test can see how they ended.
void becomeSubreaper() { ASSERT_EQ(::prctl(PR_SET_CHILD_SUBREAPER, 1), 0); }

TEST(ChildProcessTest, ExchangesLinesInOrder) {
  ChildProcess cat(talking({"cat"}));
  std::string line;
  for (const std::string text : {"first", "second one", ""}) {
    ASSERT_EQ(cat.exchange(text + "\n", line, in(30), 100), ChildProcess::LineStatus::kLine);
    EXPECT_EQ(line, text);
  }
  EXPECT_EQ(cat.pendingOutput(), 0u);
  cat.closeStdin();
  const std::optional<ChildExit> exit = cat.waitUntil(in(30));
  ASSERT_TRUE(exit.has_value());
  EXPECT_TRUE(exit->success());
  EXPECT_EQ(exit->text(), "exited with status 0");
}

TEST(ChildProcessTest, ARequestLargerThanThePipeIsWrittenWhileTheAnswerIsRead) {
  // cat answers while it is still being written to: both pipes must be served at once.
  ChildProcess cat(talking({"cat"}));
  const std::string big(1 << 20, 'x');
  std::string line;
  ASSERT_EQ(cat.exchange(big + "\n", line, in(60), big.size() + 1),
            ChildProcess::LineStatus::kLine);
  EXPECT_EQ(line.size(), big.size());
}

TEST(ChildProcessTest, TimesOutWithoutAnAnswer) {
  ChildProcess quiet(talking({"sleep", "30"}));
  std::string line;
  EXPECT_EQ(quiet.exchange("", line, in(0.2), 100), ChildProcess::LineStatus::kTimeout);
  EXPECT_FALSE(quiet.waitUntil(in(0.05)).has_value());
  EXPECT_EQ(quiet.kill().text(), "was killed by signal 9 (SIGKILL)");
}

TEST(ChildProcessTest, ALineBeyondTheLimitIsTooLong) {
  ChildProcess cat(talking({"cat"}));
  std::string line;
  EXPECT_EQ(cat.exchange(std::string(300, 'y') + "\n", line, in(30), 100),
            ChildProcess::LineStatus::kTooLong);
}

TEST(ChildProcessTest, WritingToAProgramThatClosedItsInputIsClosedNotSigpipe) {
  // SIGPIPE's default action would end this test's process.
  ChildProcess closer(talking({"sh", "-c", "exec 0<&-; echo closed; exec sleep 60"}));
  std::string line;
  ASSERT_EQ(closer.exchange("", line, in(30), 100), ChildProcess::LineStatus::kLine);
  EXPECT_EQ(closer.exchange(std::string(1 << 17, 'z'), line, in(30), 100),
            ChildProcess::LineStatus::kClosed);
  sigset_t pending;
  sigemptyset(&pending);
  sigpending(&pending);
  EXPECT_EQ(sigismember(&pending, SIGPIPE), 0) << "the failed write's SIGPIPE was left pending";
  EXPECT_EQ(closer.kill().signal, SIGKILL);
}

TEST(ChildProcessTest, KeepsTheTailOfStandardErrorAndQuotesItsLastLine) {
  // 100 kB on standard error, then a last line and trailing blank lines.
  ChildProcess noisy({{"sh", "-c",
                       "i=0; while [ $i -lt 2000 ]; do echo 'noise noise noise noise noise "
                       "noise noise' >&2; i=$((i+1)); done; printf 'Bad: \\033[31mred\\n\\n \\n' "
                       ">&2; exit 2"},
                      false,
                      false});
  const std::optional<ChildExit> exit = noisy.waitUntil(in(60));
  ASSERT_TRUE(exit.has_value());
  EXPECT_EQ(exit->exit_code, 2);
  EXPECT_EQ(noisy.stderrTail().size(), ChildProcess::kStderrTailBytes);
  EXPECT_EQ(noisy.lastErrorLine(), "Bad: \\x1b[31mred");
}

TEST(ChildProcessTest, StandardOutputJoinsStandardErrorWhenNotAPipe) {
  ChildProcess talker({{"sh", "-c", "echo on stdout"}, false, false});
  ASSERT_TRUE(talker.waitUntil(in(30)).has_value());
  EXPECT_EQ(talker.lastErrorLine(), "on stdout");
}

TEST(ChildProcessTest, AProgramThatCannotRunIsAnErrorNamingIt) {
  EXPECT_THROW(ChildProcess({{"parksim-no-such-program"}}), Error);
  const std::string script = ::testing::TempDir() + "/parksim-not-a-program";
  ASSERT_EQ(std::system(("printf '\\177ELF junk' > " + script + " && chmod 644 " + script).c_str()),
            0);
  try {
    ChildProcess p({{script}});
    FAIL() << "started " << p.pid();
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), script + ": not an executable file");
  }
  // Executable, but not a program the kernel can run: exec's own error.
  ASSERT_EQ(::chmod(script.c_str(), 0755), 0);
  try {
    ChildProcess p({{script}});
    FAIL() << "started " << p.pid();
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "cannot run " + script + ": Exec format error");
  }
}

TEST(ChildProcessTest, KillEndsTheWholeProcessGroup) {
  becomeSubreaper();
  pid_t grandchild = 0;
  {
    // The shell starts a grandchild and prints its pid; then both wait.
    ChildProcess shell(talking({"sh", "-c", "sleep 60 & echo $!; wait"}));
    std::string line;
    ASSERT_EQ(shell.exchange("", line, in(30), 100), ChildProcess::LineStatus::kLine);
    grandchild = std::stoi(line);
    EXPECT_EQ(shell.kill().signal, SIGKILL);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(grandchild, &status, 0), grandchild);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << status;
}

TEST(ChildProcessTest, WhatAnExitedProgramLeftRunningIsKilledToo) {
  becomeSubreaper();
  ChildProcess shell(talking({"sh", "-c", "sleep 60 >/dev/null 2>&1 & echo $!"}));
  std::string line;
  ASSERT_EQ(shell.exchange("", line, in(30), 100), ChildProcess::LineStatus::kLine);
  const pid_t grandchild = std::stoi(line);
  const std::optional<ChildExit> exit = shell.waitUntil(in(30));
  ASSERT_TRUE(exit.has_value());
  EXPECT_TRUE(exit->success());
  int status = 0;
  ASSERT_EQ(::waitpid(grandchild, &status, 0), grandchild);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << status;
}

TEST(ChildProcessTest, TheDestructorLeavesNoProcessAndNoZombie) {
  pid_t pid = 0;
  {
    ChildProcess p(talking({"sleep", "60"}));
    pid = p.pid();
    EXPECT_EQ(::kill(pid, 0), 0);
  }
  // Reaped: the pid is gone (not even a zombie of this process is left to wait for).
  EXPECT_EQ(::waitpid(pid, nullptr, WNOHANG), -1);
  EXPECT_EQ(errno, ECHILD);
}

TEST(ChildProcessTest, KillChildProcessGroupsEndsEveryLiveGroup) {
  ChildProcess a(talking({"sleep", "60"}));
  ChildProcess b(talking({"sleep", "60"}));
  killChildProcessGroups();
  for (ChildProcess* p : {&a, &b}) {
    const std::optional<ChildExit> exit = p->waitUntil(in(30));
    ASSERT_TRUE(exit.has_value());
    EXPECT_EQ(exit->signal, SIGKILL);
  }
}

}  // namespace
}  // namespace parksim
