// framedyn replaces only results it wrote (core/results_folder.h, issue 14
// item 1): every results folder carries a manifest of its files; a re-run
// replaces it deleting only the listed files; a file, a folder of the user's,
// results the user added a file to, the working directory, a folder above it
// and a folder holding an input are refused, and left byte for byte as they
// were; a re-run swaps the new folder with the old one in one step, so a
// watcher never finds the results folder absent.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <atomic>
#include <cstdio>
#include <thread>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "core/error.h"
#include "core/results_folder.h"
#include "tests/support/temp_dir.h"

namespace {

namespace fs = std::filesystem;
using framedyn::core::InputError;
using framedyn::core::ResultsFolder;
using framedyn::testing::TempDir;

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::map<std::string, std::string> tree(const fs::path& dir) {
  std::map<std::string, std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    out[fs::relative(e.path(), dir).generic_string()] = e.is_directory() ? "<folder>" : read(e.path());
  return out;
}

void write_run(const fs::path& target, const std::string& text, const std::vector<fs::path>& inputs = {}) {
  ResultsFolder folder(target, inputs);
  folder.write_text("summary.json", text);
  folder.write_text("response.csv", "time [s]\n0\n");
  folder.commit();
}

// The refusal's message, or "" if the run was accepted.
std::string refusal(const fs::path& target, const std::vector<fs::path>& inputs = {}) {
  try {
    write_run(target, "{\"new\": true}\n", inputs);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ResultsFolder, ANewFolderHoldsItsFilesAndAManifestListingThem) {
  TempDir dir;
  write_run(dir / "out", "{}\n");
  EXPECT_EQ(read(dir / "out" / ".framedyn-manifest").substr(0, 27), "# framedyn results manifest");
  const std::string manifest = read(dir / "out" / ".framedyn-manifest");
  EXPECT_NE(manifest.find("\nresponse.csv\n"), std::string::npos) << manifest;
  EXPECT_NE(manifest.find("\nsummary.json\n"), std::string::npos) << manifest;
  EXPECT_EQ(tree(dir.path()).size(), 4u);  // out, its two files and the manifest; no partial or old folder
}

TEST(ResultsFolder, ARerunReplacesEarlierResultsItWrote) {
  TempDir dir;
  write_run(dir / "out", "{\"run\": 1}\n");
  write_run(dir / "out/", "{\"run\": 2}\n");  // a trailing slash names the same folder
  EXPECT_EQ(read(dir / "out" / "summary.json"), "{\"run\": 2}\n");
  EXPECT_EQ(tree(dir.path()).size(), 4u);
}

TEST(ResultsFolder, AnEmptyFolderIsReplaced) {
  TempDir dir;
  fs::create_directory(dir / "out");
  EXPECT_EQ(refusal(dir / "out"), "");
  EXPECT_TRUE(fs::exists(dir / "out" / "summary.json"));
}

TEST(ResultsFolder, AFileTheUserAddedToEarlierResultsIsKeptAndTheRunRefused) {
  TempDir dir;
  write_run(dir / "out", "{\"run\": 1}\n");
  dir.write("out/notes.txt", "my notes\n");
  dir.write("out/plots/mine.png", "png");
  const auto before = tree(dir.path());
  const std::string m = refusal(dir / "out");
  EXPECT_NE(m.find("command line: --out: expected a results folder framedyn may replace"), std::string::npos) << m;
  EXPECT_NE(m.find("notes.txt"), std::string::npos) << m;
  EXPECT_NE(m.find("plots/"), std::string::npos) << m;
  EXPECT_EQ(tree(dir.path()), before);
}

TEST(ResultsFolder, AFolderWithoutManifestIsRefusedAndKept) {
  TempDir dir;
  dir.write("mine/thesis.tex", "chapter 1\n");
  const auto before = tree(dir.path());
  const std::string m = refusal(dir / "mine");
  EXPECT_NE(m.find("a folder framedyn did not write"), std::string::npos) << m;
  EXPECT_EQ(tree(dir.path()), before);
}

TEST(ResultsFolder, ARegularFileIsRefusedAndKept) {
  TempDir dir;
  dir.write("precious.txt", "keep me\n");
  const std::string m = refusal(dir / "precious.txt");
  EXPECT_NE(m.find("a file that is not a folder"), std::string::npos) << m;
  EXPECT_EQ(read(dir / "precious.txt"), "keep me\n");
  EXPECT_EQ(tree(dir.path()).size(), 1u);
}

TEST(ResultsFolder, TheWorkingDirectoryAndTheFoldersAboveItAreRefused) {
  TempDir dir;
  dir.write("work/.framedyn-manifest", "# framedyn results manifest 1\n");  // even a results folder
  const fs::path here = fs::current_path();
  fs::current_path(dir / "work");
  const std::string dot = refusal("."), up = refusal(".."), absolute = refusal(dir / "work");
  fs::current_path(here);
  EXPECT_NE(dot.find("the working directory"), std::string::npos) << dot;
  EXPECT_NE(up.find("the working directory or a folder above it"), std::string::npos) << up;
  EXPECT_NE(absolute.find("the working directory"), std::string::npos) << absolute;
  EXPECT_EQ(tree(dir.path()).size(), 2u);
}

TEST(ResultsFolder, TheFolderHoldingAnInputIsRefused) {
  TempDir dir;
  write_run(dir / "out", "{}\n");
  dir.write("out/study.yaml", "framedyn_study: 1\n");
  const std::string m = refusal(dir / "out", {dir / "out" / "study.yaml"});
  EXPECT_NE(m.find("the folder holding the input file"), std::string::npos) << m;
  EXPECT_TRUE(fs::exists(dir / "out" / "study.yaml"));
}

TEST(ResultsFolder, AFileAddedDuringTheRunIsFoundAtTheCommitAndNothingIsLost) {
  TempDir dir;
  write_run(dir / "out", "{\"run\": 1}\n");
  ResultsFolder folder(dir / "out");
  folder.write_text("summary.json", "{\"run\": 2}\n");
  dir.write("out/notes.txt", "written while framedyn ran\n");
  EXPECT_THROW(folder.commit(), InputError);
  EXPECT_EQ(read(dir / "out" / "summary.json"), "{\"run\": 1}\n");
  EXPECT_EQ(read(dir / "out" / "notes.txt"), "written while framedyn ran\n");
}

TEST(ResultsFolder, AnUncommittedRunLeavesNoPartialFolder) {
  TempDir dir;
  {
    ResultsFolder folder(dir / "out");
    folder.write_text("summary.json", "{}\n");
  }
  EXPECT_TRUE(fs::is_empty(dir.path()));
}

// Runs replacing their results 300 times while a second thread stats the
// results folder as fast as it can: the folder is there at every look (the
// swap is one renameat2(RENAME_EXCHANGE); two renames would leave a moment
// with nothing at the path), and each run leaves no partial or old folder.
TEST(ResultsFolder, ARerunSwapsTheFoldersSoTheResultsFolderIsNeverAbsent) {
  TempDir dir;
  const fs::path out = dir / "out";
  write_run(out, "{\"run\": 0}\n");
  std::atomic<bool> stop{false};
  std::atomic<long> looks{0}, absent{0};
  std::thread watcher([&] {
    struct stat st {};
    while (!stop) {
      if (::stat(out.c_str(), &st) != 0 || !S_ISDIR(st.st_mode)) ++absent;
      ++looks;
    }
  });
  constexpr int kRuns = 300;
  for (int run = 1; run <= kRuns; ++run) write_run(out, "{\"run\": " + std::to_string(run) + "}\n");
  stop = true;
  watcher.join();
  std::printf("[ measured ] %d replacements, %ld looks at the results folder, %ld found it absent\n", kRuns, looks.load(), absent.load());
  EXPECT_EQ(absent.load(), 0);
  EXPECT_GT(looks.load(), kRuns);  // the watcher ran through the replacements
  EXPECT_EQ(read(out / "summary.json"), "{\"run\": " + std::to_string(kRuns) + "}\n");
  EXPECT_EQ(tree(dir.path()).size(), 4u);  // out, its two files and the manifest: the swapped-out folders are gone
}

}  // namespace
