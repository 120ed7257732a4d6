// Loading program files (src/lang/source_file.hpp): regular files are read (mapped), anything
// else is refused with a reason and without blocking (a FIFO would block a plain open()).
#include "lang/source_file.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace ncoffset::lang {
namespace {

namespace fs = std::filesystem;

class SourceFileLoad : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("ncoffset_source_file_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(SourceFileLoad, ReadsARegularFile) {
  std::ofstream(dir_ / "P.MPF") << "G1 X1 F100\nM30\n";
  std::string err;
  auto f = SourceFile::load(dir_ / "P.MPF", &err);
  ASSERT_TRUE(f) << err;
  EXPECT_EQ(f->text(), "G1 X1 F100\nM30\n");
}

TEST_F(SourceFileLoad, ReadsAnEmptyFile) {
  std::ofstream(dir_ / "E.MPF").flush();
  std::string err;
  auto f = SourceFile::load(dir_ / "E.MPF", &err);
  ASSERT_TRUE(f) << err;
  EXPECT_TRUE(f->text().empty());
}

TEST_F(SourceFileLoad, RefusesAFifoWithoutBlocking) {
  ASSERT_EQ(::mkfifo((dir_ / "F.MPF").c_str(), 0600), 0);
  std::string err;
  EXPECT_FALSE(SourceFile::load(dir_ / "F.MPF", &err));
  EXPECT_EQ(err, "not a regular file (a FIFO)");
}

TEST_F(SourceFileLoad, RefusesADirectoryAndADevice) {
  std::string err;
  EXPECT_FALSE(SourceFile::load(dir_, &err));
  EXPECT_EQ(err, "is a directory");
  EXPECT_FALSE(SourceFile::load("/dev/null", &err));
  EXPECT_EQ(err, "not a regular file (a device)");
}

TEST_F(SourceFileLoad, NamesTheReasonForAMissingFile) {
  std::string err;
  EXPECT_FALSE(SourceFile::load(dir_ / "NONE.MPF", &err));
  EXPECT_EQ(err, "No such file or directory");
}

}  // namespace
}  // namespace ncoffset::lang
