#include "azt/linux/atomic_file.hpp"

#include <dirent.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <iostream>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

namespace azt::linux_os {
namespace {

/// A fresh directory per test, removed (with its files) afterwards.
class AtomicFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern =
        std::string(tmp != nullptr && *tmp != '\0' ? tmp : "/tmp") + "/azt_atomic_file_XXXXXX";
    std::vector<char> buffer(pattern.begin(), pattern.end());
    buffer.push_back('\0');
    ASSERT_NE(::mkdtemp(buffer.data()), nullptr);
    dir_ = buffer.data();
  }

  void TearDown() override {
    for (const auto& name : entries()) {
      const std::string full = dir_ + "/" + name;
      if (::unlink(full.c_str()) != 0) ::rmdir(full.c_str());
    }
    ::rmdir(dir_.c_str());
  }

  [[nodiscard]] std::vector<std::string> entries() const {
    std::vector<std::string> names;
    DIR* d = ::opendir(dir_.c_str());
    if (d == nullptr) return names;
    while (const dirent* e = ::readdir(d)) {
      const std::string name = e->d_name;
      if (name != "." && name != "..") names.push_back(name);
    }
    ::closedir(d);
    return names;
  }

  [[nodiscard]] std::string file(const std::string& name) const { return dir_ + "/" + name; }

  std::string dir_;
};

Result<bool> accept_all(std::string_view /*text*/) { return true; }

Result<bool> reject_corrupt(std::string_view text) {
  if (text.starts_with("corrupt")) return fail("checksum mismatch");
  return true;
}

TEST_F(AtomicFileTest, RoundTrip) {
  const std::string path = file("state.toml");
  const std::string contents = std::string("az = 123.5\n") + std::string(1, '\0') + "tail\n";
  ASSERT_TRUE(write_file_atomically(path, contents).ok());
  auto read = read_file(path);
  ASSERT_TRUE(read.ok()) << read.error().message;
  EXPECT_EQ(*read, contents);

  ASSERT_TRUE(write_file_atomically(path, "").ok());
  read = read_file(path);
  ASSERT_TRUE(read.ok());
  EXPECT_EQ(*read, "");
}

TEST_F(AtomicFileTest, NewFileGets0644AndExistingModeIsKept) {
  const std::string path = file("state.toml");
  ASSERT_TRUE(write_file_atomically(path, "one").ok());
  struct stat st {};
  ASSERT_EQ(::stat(path.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 07777, 0644u);

  ASSERT_EQ(::chmod(path.c_str(), 0600), 0);
  ASSERT_TRUE(write_file_atomically(path, "two").ok());
  ASSERT_EQ(::stat(path.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 07777, 0600u);
}

TEST_F(AtomicFileTest, BackupHoldsPreviousContents) {
  const std::string path = file("state.toml");
  ASSERT_TRUE(write_file_atomically(path, "first").ok());
  EXPECT_FALSE(read_file(path + ".bak").ok()) << "no backup before there was a previous version";

  ASSERT_TRUE(write_file_atomically(path, "second").ok());
  EXPECT_EQ(*read_file(path), "second");
  EXPECT_EQ(*read_file(path + ".bak"), "first");

  ASSERT_TRUE(write_file_atomically(path, "third").ok());
  EXPECT_EQ(*read_file(path), "third");
  EXPECT_EQ(*read_file(path + ".bak"), "second");
}

TEST_F(AtomicFileTest, LeavesNoTempFilesBehind) {
  const std::string path = file("state.toml");
  for (int i = 0; i < 5; ++i) {
    ASSERT_TRUE(write_file_atomically(path, "version " + std::to_string(i)).ok());
  }
  auto names = entries();
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"state.toml", "state.toml.bak"}));
}

TEST_F(AtomicFileTest, MissingParentDirectoryFailsWithStepAndReason) {
  auto result = write_file_atomically(file("no/such/dir/state.toml"), "x");
  ASSERT_FALSE(result.ok());
  EXPECT_NE(result.error().message.find("create temp file"), std::string::npos)
      << result.error().message;
  EXPECT_NE(result.error().message.find("No such file or directory"), std::string::npos)
      << result.error().message;
}

TEST_F(AtomicFileTest, FailedWriteLeavesOldFileAndBackupIntact) {
  const std::string path = file("state.toml");
  ASSERT_TRUE(write_file_atomically(path, "old").ok());
  ASSERT_TRUE(write_file_atomically(path, "current").ok());
  // Occupy the temp name with a directory so the temp file cannot be created (works as root too).
  const std::string blocker = path + ".tmp." + std::to_string(::getpid());
  ASSERT_EQ(::mkdir(blocker.c_str(), 0755), 0);
  // write_durable_temp unlinks a stale temp first; unlink cannot remove a directory, so this fails.
  auto result = write_file_atomically(path, "new");
  EXPECT_FALSE(result.ok());
  EXPECT_EQ(*read_file(path), "current");
  EXPECT_EQ(*read_file(path + ".bak"), "old");
  ASSERT_EQ(::rmdir(blocker.c_str()), 0);

  auto names = entries();
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"state.toml", "state.toml.bak"}));
}

TEST_F(AtomicFileTest, PathThatIsADirectoryFailsAndIsUntouched) {
  const std::string path = file("adir");
  ASSERT_EQ(::mkdir(path.c_str(), 0755), 0);
  auto result = write_file_atomically(path, "x");
  ASSERT_FALSE(result.ok());
  struct stat st {};
  ASSERT_EQ(::stat(path.c_str(), &st), 0);
  EXPECT_TRUE(S_ISDIR(st.st_mode));
  EXPECT_EQ(entries(), std::vector<std::string>{"adir"});
  EXPECT_FALSE(read_file(path).ok());
}

TEST_F(AtomicFileTest, ReadFileRejectsOversizedFiles) {
  const std::string path = file("big");
  ASSERT_TRUE(write_file_atomically(path, std::string(kMaxReadBytes + 1, 'x')).ok());
  auto result = read_file(path);
  ASSERT_FALSE(result.ok());
  EXPECT_NE(result.error().message.find("larger than"), std::string::npos);

  ASSERT_TRUE(write_file_atomically(path, std::string(kMaxReadBytes, 'x')).ok());
  EXPECT_TRUE(read_file(path).ok());
}

TEST_F(AtomicFileTest, LoadUsesPrimaryWhenValid) {
  const std::string path = file("state.toml");
  ASSERT_TRUE(write_file_atomically(path, "good 1").ok());
  ASSERT_TRUE(write_file_atomically(path, "good 2").ok());
  auto loaded = load_with_backup(path, reject_corrupt);
  ASSERT_TRUE(loaded.ok()) << loaded.error().message;
  EXPECT_EQ(loaded->text, "good 2");
  EXPECT_FALSE(loaded->from_backup);
  EXPECT_TRUE(loaded->warning.empty());
}

TEST_F(AtomicFileTest, LoadFallsBackOnCorruptPrimary) {
  const std::string path = file("state.toml");
  ASSERT_TRUE(write_file_atomically(path, "good").ok());
  ASSERT_TRUE(write_file_atomically(path, "corrupt!").ok());
  auto loaded = load_with_backup(path, reject_corrupt);
  ASSERT_TRUE(loaded.ok()) << loaded.error().message;
  EXPECT_EQ(loaded->text, "good");
  EXPECT_TRUE(loaded->from_backup);
  EXPECT_NE(loaded->warning.find("checksum mismatch"), std::string::npos) << loaded->warning;
  EXPECT_NE(loaded->warning.find(".bak"), std::string::npos) << loaded->warning;
}

TEST_F(AtomicFileTest, LoadFallsBackOnMissingPrimary) {
  const std::string path = file("state.toml");
  ASSERT_TRUE(write_file_atomically(path, "good").ok());
  ASSERT_TRUE(write_file_atomically(path, "newer").ok());
  ASSERT_EQ(::unlink(path.c_str()), 0);
  auto loaded = load_with_backup(path, accept_all);
  ASSERT_TRUE(loaded.ok()) << loaded.error().message;
  EXPECT_EQ(loaded->text, "good");
  EXPECT_TRUE(loaded->from_backup);
  EXPECT_NE(loaded->warning.find("No such file or directory"), std::string::npos)
      << loaded->warning;
}

TEST_F(AtomicFileTest, LoadFailsNamingBothProblemsWhenNeitherIsUsable) {
  const std::string path = file("state.toml");
  auto missing = load_with_backup(path, accept_all);
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.error().message.find("backup"), std::string::npos);

  ASSERT_TRUE(write_file_atomically(path, "corrupt 1").ok());
  ASSERT_TRUE(write_file_atomically(path, "corrupt 2").ok());
  auto both_bad = load_with_backup(path, reject_corrupt);
  ASSERT_FALSE(both_bad.ok());
  EXPECT_NE(both_bad.error().message.find("invalid too"), std::string::npos)
      << both_bad.error().message;
}

// kill -9 at a random instant while a child rewrites the file in a loop: the file (and its backup)
// must always be exactly one complete version.
TEST_F(AtomicFileTest, SigkillNeverLeavesATornFile) {
  constexpr int kIterations = 200;
  const std::string version_a = std::string(64 * 1024, 'a') + "END\n";
  const std::string version_b = std::string(64 * 1024, 'b') + "END\n";
  const std::string path = file("state.toml");
  ASSERT_TRUE(write_file_atomically(path, version_a).ok());

  std::mt19937_64 rng(0x5eed'a2e1'7ac0ULL);
  std::uniform_int_distribution<int> sleep_us(0, 20'000);
  int seen_a = 0;
  int seen_b = 0;
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < kIterations; ++i) {
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      // Start with whichever version is not on disk, so every completed save changes the file.
      auto current = read_file(path);
      bool write_a = current.ok() && *current == version_b;
      for (;;) {
        if (!write_file_atomically(path, write_a ? version_a : version_b).ok()) ::_exit(2);
        write_a = !write_a;
      }
    }
    std::this_thread::sleep_for(std::chrono::microseconds(sleep_us(rng)));
    ASSERT_EQ(::kill(child, SIGKILL), 0);
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL)
        << "child exited early, status " << status;

    auto contents = read_file(path);
    ASSERT_TRUE(contents.ok()) << "iteration " << i << ": " << contents.error().message;
    ASSERT_TRUE(*contents == version_a || *contents == version_b)
        << "iteration " << i << ": torn file of " << contents->size() << " bytes";
    (*contents == version_a ? seen_a : seen_b) += 1;
    if (auto backup = read_file(path + ".bak"); backup.ok()) {
      ASSERT_TRUE(*backup == version_a || *backup == version_b)
          << "iteration " << i << ": torn backup of " << backup->size() << " bytes";
    }
    auto loaded = load_with_backup(path, accept_all);
    ASSERT_TRUE(loaded.ok());
    EXPECT_FALSE(loaded->from_backup);

    // The killed child's temp files are expected debris; clear them so the directory stays small.
    const std::string child_pid = std::to_string(child);
    ::unlink((path + ".tmp." + child_pid).c_str());
    ::unlink((path + ".bak.tmp." + child_pid).c_str());
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "[ kill -9 ] " << kIterations << " iterations in " << seconds << " s; saw A "
            << seen_a << " times, B " << seen_b << " times\n";
  RecordProperty("kill_loop_seconds", std::to_string(seconds));
  EXPECT_LT(seconds, 15.0);
}

// publish_file (azel.dat, docs/eme.md): atomic for readers, no backup, no temp left behind.
TEST_F(AtomicFileTest, PublishReplacesWholeWithoutABackup) {
  const std::string path = file("azel.dat");
  ASSERT_TRUE(publish_file(path, "first\n"));
  struct stat st {};
  ASSERT_EQ(::stat(path.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0644U);
  ASSERT_EQ(::chmod(path.c_str(), 0600), 0);
  ASSERT_TRUE(publish_file(path, "second\n"));
  EXPECT_EQ(read_file(path).value(), "second\n");
  ASSERT_EQ(::stat(path.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 07777, 0644U) << "a fixed mode, never the old file's";
  EXPECT_EQ(entries(), std::vector<std::string>{"azel.dat"}) << "no .bak, no temp";
}

// docs/reliability.md "Hardening, round three" row 4: a symlink planted at the export path,
// pointing to a setuid file, had given the new azel.dat mode 4755. The link itself is replaced; its
// target keeps its bits and contents.
TEST_F(AtomicFileTest, PublishOverASymlinkNeitherCopiesNorTouchesItsTarget) {
  const std::string target = file("setuid-program");
  ASSERT_TRUE(publish_file(target, "#!/bin/sh\n"));
  ASSERT_EQ(::chmod(target.c_str(), 04755), 0);
  const std::string path = file("azel.dat");
  ASSERT_EQ(::symlink(target.c_str(), path.c_str()), 0);
  ASSERT_TRUE(publish_file(path, "AZ 10.0 EL 20.0\n"));
  struct stat st {};
  ASSERT_EQ(::lstat(path.c_str(), &st), 0);
  EXPECT_TRUE(S_ISREG(st.st_mode)) << "the link was replaced by a file";
  EXPECT_EQ(st.st_mode & 07777, 0644U);
  ASSERT_EQ(::stat(target.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 07777, 04755U);
  EXPECT_EQ(read_file(target).value(), "#!/bin/sh\n");
}

TEST_F(AtomicFileTest, PublishedModeFollowsTheUmask) {
  const mode_t old_mask = ::umask(027);
  const auto written = publish_file(file("azel.dat"), "x\n");
  ::umask(old_mask);
  ASSERT_TRUE(written);
  struct stat st {};
  ASSERT_EQ(::stat(file("azel.dat").c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 07777, 0640U);
}

TEST_F(AtomicFileTest, PublishIntoAMissingFolderFailsAndLeavesNothing) {
  const auto r = publish_file(file("no-such-dir/azel.dat"), "x");
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("create temp file"), std::string::npos) << r.error().message;
  EXPECT_TRUE(entries().empty());
  EXPECT_FALSE(publish_file("", "x"));
}

TEST_F(AtomicFileTest, APublishedFileIsNeverSeenTorn) {
  // A reader polling as fast as it can sees only whole versions while the file is rewritten.
  const std::string path = file("azel.dat");
  const std::string a(4096, 'a');
  const std::string b(8192, 'b');
  ASSERT_TRUE(publish_file(path, a));
  std::atomic<bool> done{false};
  int torn = 0;
  std::thread reader([&] {
    while (!done) {
      const auto text = read_file(path);
      if (text && text.value() != a && text.value() != b) ++torn;
    }
  });
  for (int i = 0; i < 2000; ++i) ASSERT_TRUE(publish_file(path, i % 2 == 0 ? b : a));
  done = true;
  reader.join();
  EXPECT_EQ(torn, 0);
}

}  // namespace
}  // namespace azt::linux_os
