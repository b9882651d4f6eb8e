// Progress lines on stderr for work that takes more than a second: a stage
// is announced only once the run has been going for a second (or at once
// with --verbose), so quick runs stay quiet and long ones show where they are.
#pragma once

#include <chrono>
#include <functional>
#include <string>

namespace framedyn::apps {

class Progress {
 public:
  explicit Progress(bool verbose = false, bool quiet = false);
  void stage(const std::string& what);
  void done();
  std::function<void(const std::string&)> callback();

 private:
  std::chrono::steady_clock::time_point start_;
  std::string pending_;
  bool verbose_, quiet_, announced_ = false;
  double elapsed() const;
};

}  // namespace framedyn::apps
