// A frame's beam model built once per worker; see frame_model_cache.h.
#include "coupling/frame_model_cache.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>

#include "coupling/frame_study.h"

namespace framedyn::coupling {

const FrameBuild* FrameModelCache::find(const std::string& key) {
  if (key.empty()) return nullptr;
  for (const auto& b : kept_)
    if (b->key == key) {
      ++reused_;
      return b.get();
    }
  return nullptr;
}

void FrameModelCache::keep(std::unique_ptr<FrameBuild> build) {
  ++built_;
  kept_.push_back(std::move(build));
  if (kept_.size() > kCapacity) kept_.erase(kept_.begin());
}

std::string frame_build_key(const FrameStudyRequest& q) {
  std::ifstream in(q.mesh, std::ios::binary);
  if (!in) return "";
  std::stringstream bytes;
  bytes << in.rdbuf();
  std::string key = bytes.str();
  std::string upper(key.size(), ' ');
  std::transform(key.begin(), key.end(), upper.begin(), [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  if (upper.find("*INCLUDE") != std::string::npos) return "";
  // Numbers as the shortest text that reads back to the same double: equal text, equal bits.
  key += fmt::format("\n-- mesh {} units {} convert {} supports {} method {} modes {} sets", q.mesh.string(), q.units.name(), q.convert_units,
                     static_cast<int>(q.supports), static_cast<int>(q.method), q.modes);
  for (const std::string& s : q.support_sets) key += " " + s;
  // How the mesh is read: the CIRC dialect and the study's section dimensions (frame.sections) change the model.
  key += fmt::format("\n-- inp_dialect {}", q.inp_dialect ? (*q.inp_dialect == fem::InpDialect::calculix ? "calculix" : "abaqus") : "unset");
  key += section_overrides_key(q.sections);
  for (const FramePart& p : q.parts) {
    const rigid::RigidPart3D& b = p.part;
    key += fmt::format("\n-- part {} mass {} cg {} {} {} inertia", b.name, b.mass, b.cg.x(), b.cg.y(), b.cg.z());
    for (int i = 0; i < 9; ++i) key += fmt::format(" {}", b.inertia(i / 3, i % 3));
    key += " mounts";
    for (const PartMount& m : p.mounts)
      key += m.by_point ? fmt::format(" [{} {} {}]", m.point.x(), m.point.y(), m.point.z()) : fmt::format(" {}", m.node);
  }
  return key;
}

}  // namespace framedyn::coupling
