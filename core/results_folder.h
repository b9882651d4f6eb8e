// A results folder that is whole or absent. Files are written into a sibling
// folder "<target>.partial-<pid>"; commit() moves it into place in one rename,
// so a run that stops half-way (an error, an exception) leaves any previous
// results untouched and no partial folder that looks complete.
#pragma once

#include <filesystem>
#include <string>

namespace framedyn::core {

class ResultsFolder {
 public:
  explicit ResultsFolder(std::filesystem::path target);
  ~ResultsFolder();  // removes the partial folder unless committed
  ResultsFolder(const ResultsFolder&) = delete;
  ResultsFolder& operator=(const ResultsFolder&) = delete;

  // Path of a file inside the (still partial) folder, for writers that open files themselves.
  std::filesystem::path path_of(const std::string& file_name) const;
  void write_text(const std::string& file_name, const std::string& content) const;
  // Replace the target by the partial folder. Throws std::runtime_error on failure.
  void commit();
  const std::filesystem::path& target() const { return target_; }

 private:
  std::filesystem::path target_;
  std::filesystem::path partial_;
  bool committed_ = false;
};

}  // namespace framedyn::core
