// Frame section dimensions as study keys (issue 19: "frame section dimensions
// (a named section of the mesh)" as design parameters): the `sections` key of
// the block that reads the frame mesh (frame-response's `frame`, a 3-D
// study's `frame_response`), a map from element set to dimensions named as
// Abaqus names them for the set's section type:
//
//   frame_response:
//     mesh: ../meshes/r100_frame.inp
//     sections: {RAILS: {t1: 0.3125, t3: 0.3125}}
//
//   RECT a, b        BOX a, b, t1, t2, t3, t4     PIPE r, t
//   CIRC r (one value) or a, b (CalculiX's two-value ellipse)
//   I l, h, b1, b2, t1, t2, t3                    CHANNEL h, b, tf, tw
//
// The values are lengths in the study's units (converted to the mesh's units
// when the two differ, under convert_units). The override rewrites the data
// line of the set's *BEAM SECTION in the mesh text before the mesh is read
// (docs/theory/coupling.md section 16), so the changed section is exactly the
// section the mesh would have with those numbers written in it: its A, I, J,
// stress points, mass (the vehicle model's frame mass too, when the mesh is
// the frame structure's mass source) and modes. A batch parameter or
// Study.set reaches a value by its key path
// (frame_response.sections.RAILS.t1); the key must be in the base study.
// Errors STUDY-150..154 (docs/errors.md).
#pragma once

#include <string>
#include <vector>

#include "core/error.h"
#include "core/units.h"

namespace framedyn::coupling {

class YamlMap;

struct SectionDimension {
  std::string name;               // as written (a, t1, ...)
  double value = 0.0;             // in the study's length unit, as written
  core::InputLocation where;      // the key's line and path (frame.sections.RAILS.t1)
};

struct SectionOverride {
  std::string element_set;        // as written; matched without regard to case, as the mesh's names are
  core::InputLocation where;      // frame.sections.RAILS
  std::vector<SectionDimension> dimensions;  // in the study's order
};

// The `sections` map of a frame block (STUDY-152: a value that is not a
// positive number; STUDY-154: one element set named twice).
std::vector<SectionOverride> read_section_overrides(const YamlMap& sections);

// Abaqus's names of a section type's dimensions, in the data line's order
// (`values` is the number of values on the line: CIRC and RECT take one or two).
std::vector<std::string> section_dimension_names(const std::string& shape, std::size_t values);

// `text` (an .inp mesh named `mesh_name` in messages) with the data line of
// each overridden set's *BEAM SECTION (and CalculiX's *BEAM GENERAL SECTION,
// SECTION=BOX or PIPE) carrying the new dimensions; every other byte is kept,
// lines included. `study_units`: the unit of the values. Throws
// core::InputError at the override's key: STUDY-150 (no section of that set in
// the mesh), STUDY-151 (a dimension the set's section type does not have),
// STUDY-153 (walls thicker than the section allows).
std::string apply_section_overrides(const std::string& text, const std::string& mesh_name, const std::vector<SectionOverride>& overrides,
                                    const core::UnitSystem& study_units);

// The overrides as exact text, for the frame-model cache's key.
std::string section_overrides_key(const std::vector<SectionOverride>& overrides);

}  // namespace framedyn::coupling
