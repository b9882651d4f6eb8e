// Reader for the subset of the Abaqus/CalculiX .inp format that beam models
// use, so that frames drawn in common pre-processors load as they are and can
// be run through CalculiX unchanged. Supported keywords and their parameters
// are listed in docs/user-guide.md ("Mesh files"); anything else is an error
// naming the file, the line and the keyword.
//
// The .inp format has no units. The unit system comes from the caller (the
// command line's --units) or from a comment line "** units: NAME" in the
// file; one of the two is required, and they must agree if both are given.
// Values are converted to SI on the way in.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "fem/frame_model.h"

namespace framedyn::fem {

// Where CalculiX and Abaqus read the same line differently
// (docs/theory/fem.md section 23): SECTION=CIRC's value(s) are radii
// (semi-axes) for Abaqus, diameters (axes) for CalculiX 2.20.
enum class InpDialect { abaqus, calculix };

struct InpReadOptions {
  std::optional<std::string> units;  // "in-lbf-s", "m-N-s" (or "SI"), "mm-N-s"
  // Unset: Abaqus's reading, and a CIRC section gets a warning naming its
  // element set and both readings (into the model's reader_warnings).
  std::optional<InpDialect> dialect;
  // How the warning tells the user to give the dialect: the command line's
  // option, or a study's key (frame.inp_dialect).
  std::string dialect_key = "--inp-dialect";
};

// Throws core::InputError (file, line, keyword, expected, found) on any problem.
FrameModel read_inp(const std::filesystem::path& path, const InpReadOptions& options = {});
// The same from text in memory; `name` is used in messages and *INCLUDE paths
// are resolved against `base_dir`.
FrameModel read_inp_text(const std::string& text, const std::string& name, const std::filesystem::path& base_dir,
                         const InpReadOptions& options = {});

}  // namespace framedyn::fem
