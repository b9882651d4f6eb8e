// No NaN or Inf in a results file; see finite_output.h.
#include "core/finite_output.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <optional>
#include <vector>

#include "core/error.h"

namespace framedyn::core {

namespace {

bool is_delimiter(char c) {
  switch (c) {
    case ',': case ' ': case '\t': case '\n': case '\r': case '"': case '\'':
    case '<': case '>': case '=': case ';': case ':': case '[': case ']': case '{': case '}':
      return true;
    default:
      return false;
  }
}

// "NaN" or "infinite" if the token spells a non-finite number, else empty.
std::string non_finite_kind(const std::string& token) {
  std::string t;
  for (char c : token) t += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  std::string sign;
  if (!t.empty() && (t[0] == '-' || t[0] == '+')) {
    sign = t[0] == '-' ? "-" : "";
    t.erase(0, 1);
  }
  if (t == "nan" || t.rfind("nan(", 0) == 0) return "NaN";
  if (t == "inf" || t == "infinity") return sign + "infinite";
  return {};
}

struct Hit {
  std::size_t position = 0;
  std::string token;
  std::string kind;
};

// The first token of `text` that spells a non-finite number. Tokens that
// start with a digit or a dot (nearly every number) are skipped unread.
std::optional<Hit> first_non_finite_token(const std::string& text) {
  const std::size_t n = text.size();
  std::size_t i = 0;
  while (i < n) {
    while (i < n && is_delimiter(text[i])) ++i;
    const std::size_t start = i;
    while (i < n && !is_delimiter(text[i])) ++i;
    const std::size_t length = i - start;
    if (length < 3 || length > 9) continue;
    const char first = text[start];
    if (std::isdigit(static_cast<unsigned char>(first)) || first == '.') continue;
    std::string token = text.substr(start, length);
    std::string kind = non_finite_kind(token);
    if (!kind.empty()) return Hit{start, std::move(token), std::move(kind)};
  }
  return std::nullopt;
}

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && std::equal(suffix.rbegin(), suffix.rend(), s.rbegin());
}

std::size_t line_start(const std::string& text, std::size_t position) {
  const std::size_t nl = position == 0 ? std::string::npos : text.rfind('\n', position - 1);
  return nl == std::string::npos ? 0 : nl + 1;
}

std::size_t line_number(const std::string& text, std::size_t position) {
  return 1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(position), '\n'));
}

std::string line_at(const std::string& text, std::size_t start) {
  const std::size_t end = text.find('\n', start);
  std::string line = text.substr(start, end == std::string::npos ? std::string::npos : end - start);
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return line;
}

// Fields of one CSV line, with "..." quoting and "" for a quote inside.
std::vector<std::string> csv_fields(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        fields.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

// Index of the CSV field of `line` that holds character `offset`.
std::size_t csv_field_index(const std::string& line, std::size_t offset) {
  std::size_t field = 0;
  bool quoted = false;
  for (std::size_t i = 0; i < offset && i < line.size(); ++i) {
    if (line[i] == '"') quoted = !quoted;
    else if (line[i] == ',' && !quoted) ++field;
  }
  return field;
}

bool is_comment(const std::string& line) { return !line.empty() && line[0] == '#'; }

std::string csv_location(const std::string& text, const Hit& hit) {
  const std::size_t hit_line_start = line_start(text, hit.position);
  const std::size_t hit_line = line_number(text, hit.position);
  // The header is the first line that is not a comment (load histories start with # lines).
  std::size_t start = 0, number = 1;
  while (start < text.size() && is_comment(line_at(text, start))) {
    const std::size_t nl = text.find('\n', start);
    if (nl == std::string::npos) break;
    start = nl + 1;
    ++number;
  }
  const std::string hit_text = line_at(text, hit_line_start);
  if (hit_line <= number || is_comment(hit_text)) return fmt::format("line {}", hit_line);
  const std::vector<std::string> header = csv_fields(line_at(text, start));
  std::size_t row = 0;  // data rows up to and including the hit's line
  for (std::size_t p = start, l = number; p < text.size() && l <= hit_line; ++l) {
    if (l > number && !is_comment(line_at(text, p))) ++row;
    const std::size_t nl = text.find('\n', p);
    if (nl == std::string::npos) break;
    p = nl + 1;
  }
  const std::size_t field = csv_field_index(hit_text, hit.position - hit_line_start);
  const std::vector<std::string> values = csv_fields(hit_text);
  std::string where = fmt::format("row {} (line {}), column \"{}\"", row, hit_line,
                                  field < header.size() ? header[field] : fmt::format("{}", field + 1));
  if (field > 0 && !header.empty() && !values.empty() && non_finite_kind(values[0]).empty())
    where += fmt::format(" (where {} = {})", header[0], values[0]);
  return where;
}

std::string vtu_location(const std::string& text, const Hit& hit) {
  const std::size_t hit_line = line_number(text, hit.position);
  const std::size_t tag = text.rfind("<DataArray", hit.position);
  if (tag == std::string::npos) return fmt::format("line {}", hit_line);
  const std::size_t tag_end = text.find('>', tag);
  std::string name = "Points";
  const std::size_t name_at = text.find("Name=\"", tag);
  if (name_at != std::string::npos && name_at < tag_end) {
    const std::size_t from = name_at + 6;
    name = text.substr(from, text.find('"', from) - from);
  }
  const std::size_t entry = hit_line - line_number(text, tag) - 1;  // one entry per line
  const std::size_t start = line_start(text, hit.position);
  std::size_t component = 0;
  bool in_token = false;
  for (std::size_t i = start; i < hit.position; ++i) {
    const bool delimiter = text[i] == ' ' || text[i] == '\t';
    if (!delimiter && !in_token) ++component;
    in_token = !delimiter;
  }
  return fmt::format("DataArray \"{}\", entry {}, component {} (both counted from 0; line {})", name, entry, component, hit_line);
}

// Keys whose null is a finding, not a broken number: steady operation not
// reached (rigid.steady.reached_at, period_multiple; docs/user-guide.md).
bool nullable_key(const std::string& key) { return key == "reached_at" || key == "period_multiple"; }

// The dotted key path of the first null in a JSON document, as in
// "frame.modes[2].frequency.value" (a nullable key's null excepted).
std::optional<std::string> first_null(const nlohmann::json& j, const std::string& path) {
  if (j.is_null()) return path.empty() ? std::string("(the whole document)") : path;
  if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it) {
      if (it.value().is_null() && nullable_key(it.key())) continue;
      if (auto p = first_null(it.value(), path.empty() ? it.key() : path + "." + it.key())) return p;
    }
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i)
      if (auto p = first_null(j[i], fmt::format("{}[{}]", path, i))) return p;
  }
  return std::nullopt;
}

[[noreturn]] void refuse(const std::string& file, const std::string& where, const std::string& what) {
  throw NumericalError(fmt::format(
      "{}: {} is {}: the computation broke down before this output (a NaN or an infinity), and framedyn writes no "
      "file with non-finite numbers, so the run stops here. Check the inputs this quantity depends on for zero, "
      "missing or extreme values, and the response for a divergence",
      file, where, what));
}

}  // namespace

void check_finite_output(const std::string& file, const std::string& content) {
  if (ends_with(file, ".json")) {
    nlohmann::json j = nlohmann::json::parse(content, nullptr, /*allow_exceptions=*/false);
    if (!j.is_discarded()) {
      if (auto path = first_null(j, ""))
        refuse(file, "key " + *path, "null (nlohmann::json writes a NaN or an infinity as null)");
      return;  // a parsed document holds only finite numbers
    }
  }
  const std::optional<Hit> hit = first_non_finite_token(content);
  if (!hit) return;
  std::string where;
  if (ends_with(file, ".csv"))
    where = csv_location(content, *hit);
  else if (ends_with(file, ".vtu"))
    where = vtu_location(content, *hit);
  else
    where = fmt::format("line {}", line_number(content, hit->position));
  refuse(file, where, fmt::format("{} (\"{}\")", hit->kind, hit->token));
}

}  // namespace framedyn::core
