// A frame's beam model built once per worker (issue 19, "each worker builds
// its models once"): what a pipeline run's frame side does not change from run
// to run when a design study varies only the vehicle's parameters (soil,
// shaker, contact coefficients): the mesh with its supports, the mounted
// parts, the rigid-body mass, the assembled and factorised frame, and its
// modes. A run with a cache takes them from it when its build key matches, so
// its numbers are the same, bit for bit, as a run that builds them (the same
// objects from the same inputs; tests/batch/test_batch.cpp checks whole
// summaries). The key is the mesh file's bytes and every request field the
// build depends on, as exact text (supports, support sets, modes, method,
// units, inp_dialect, the section dimensions of frame.sections, and each
// part's mass, c.g., inertia and mounts): a batch parameter that changes a
// part's weight or a section's wall makes a new build. A mesh with *INCLUDE is never
// reused (the included files are not in the key). One cache per worker thread
// (fem::FrameDynamics shares work buffers: not for concurrent use).
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "coupling/frame_balance.h"
#include "coupling/frame_parts.h"
#include "fem/frame_model.h"
#include "fem/modal_transient.h"

namespace framedyn::coupling {

struct FrameStudyRequest;

struct FrameBuild {
  std::string key;
  fem::FrameModel supported;  // the mesh with the study's supports (the load points are mapped onto it)
  fem::FrameModel mounted;    // the same with the parts mounted: the model `dynamics` refers to
  std::vector<MountedPart> parts;
  RigidBodyMass mass;
  std::vector<int> pin_supports;
  std::unique_ptr<const fem::FrameDynamics> dynamics;
  fem::ModalBasis basis;
};

class FrameModelCache {
 public:
  static constexpr std::size_t kCapacity = 4;  // builds kept (a run's own support and its compare_supports)
  // The build with this key, or null (an empty key is never found).
  const FrameBuild* find(const std::string& key);
  // Keeps `build` (a non-empty key), dropping the oldest beyond kCapacity.
  void keep(std::unique_ptr<FrameBuild> build);
  std::size_t builds() const { return built_; }
  std::size_t reuses() const { return reused_; }

 private:
  std::vector<std::unique_ptr<FrameBuild>> kept_;
  std::size_t built_ = 0, reused_ = 0;
};

// The build key of a request: its mesh file's bytes and the fields above; "" for a mesh with *INCLUDE.
std::string frame_build_key(const FrameStudyRequest& request);

}  // namespace framedyn::coupling
