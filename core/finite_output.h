// The last check before a results file is written: no NaN or Inf may reach an
// output file. ResultsFolder::write_text calls it for every file it writes
// (CSV tables, JSON summaries, VTU/PVD ParaView files, load histories), so
// that the writers need not check each number themselves.
#pragma once

#include <string>

namespace framedyn::core {

// Throws NumericalError if `content`, the text of the results file named
// `file` (a path, used in the message and for its extension), holds a
// non-finite number: a NaN or infinity token (as fmt and iostreams print
// them: nan, -nan, inf, -inf, also NaN, Infinity) in any file, or a null in
// a JSON file (nlohmann::json writes NaN and Inf as null). The message names
// the file and where the value is: the row and column header of a CSV table,
// the DataArray and entry of a VTU file, the key path of a JSON file, the
// line otherwise.
void check_finite_output(const std::string& file, const std::string& content);

}  // namespace framedyn::core
