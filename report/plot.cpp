// PNG line plots through gnuplot; see plot.h.
#include "report/plot.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <sstream>
#include <system_error>

#include "report/csv_writer.h"
#include "core/error.h"
#include "core/interrupt.h"

extern char** environ;

namespace framedyn::report {

using core::InputError;
using core::InputLocation;
using core::hold_output_gate;
using core::register_temporary;
using core::unregister_temporary;
using core::register_child;
using core::unregister_child;

namespace fs = std::filesystem;

namespace {

// Okabe-Ito colours: distinct for colour-blind readers and in grey print.
constexpr const char* kColours[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000"};
constexpr int kPointTypes[] = {7, 5, 9, 11, 13, 15, 4};

// A gnuplot single-quoted string: only ' is special (doubled); no line breaks.
std::string quoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) {
    if (c == '\'') out += "''";
    else if (c == '\n' || c == '\r') out += ' ';
    else out += c;
  }
  return out + "'";
}

std::string axis_title(const std::string& label, const std::string& unit) { return column(label, unit); }

// A private temporary folder, removed with the object, or by the interrupt
// clean-up (core/interrupt.h) if a signal comes first.
class ScratchDir {
 public:
  ScratchDir() {
    static std::atomic<unsigned> counter{0};
    const fs::path base = fs::temp_directory_path();
    auto gate = hold_output_gate();
    for (int attempt = 0; attempt < 1000; ++attempt) {
      path_ = base / fmt::format("framedyn_plot_{}_{}", ::getpid(), counter++);
      std::error_code ec;
      if (fs::create_directory(path_, ec)) {
        register_temporary(path_);
        return;
      }
    }
    throw PlotError("cannot create a temporary folder for the plot in " + base.string());
  }
  ~ScratchDir() {
    auto gate = hold_output_gate();
    std::error_code ec;
    fs::remove_all(path_, ec);
    unregister_temporary(path_);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

// Runs `program args...` with stdin from /dev/null and stdout + stderr into
// `log`. Returns the exit status; throws PlotError if it cannot be started or
// does not exit normally.
int run_program(const std::string& program, const std::vector<std::string>& args, const fs::path& log) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  std::vector<std::string> all = {program};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  // The child starts with no signals blocked and default dispositions, so that
  // Ctrl-C stops gnuplot too (framedyn blocks them for its interrupt clean-up).
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t none;
  sigemptyset(&none);
  posix_spawnattr_setsigmask(&attributes, &none);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK);
  pid_t pid = 0;
  int rc = 0;
  {
    // Started and registered in one hold of the gate: an interrupt either
    // comes before (no child) or finds the child registered and kills it.
    auto gate = hold_output_gate();
    rc = posix_spawnp(&pid, program.c_str(), &actions, &attributes, argv.data(), environ);
    if (rc == 0) register_child(pid);
  }
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  if (rc != 0)
    throw PlotError(fmt::format("cannot run '{}' to draw figures: {} (install gnuplot, Debian package gnuplot-nox: ./install-deps.sh)", program,
                                std::strerror(rc)));
  // Wait for the end without reaping (WNOWAIT), then reap and unregister in
  // one hold of the gate, so that the clean-up never signals a reaped pid.
  siginfo_t info{};
  while (::waitid(P_PID, static_cast<id_t>(pid), &info, WEXITED | WNOWAIT) < 0)
    if (errno != EINTR) throw PlotError(fmt::format("waiting for '{}': {}", program, std::strerror(errno)));
  int status = 0;
  {
    auto gate = hold_output_gate();
    while (::waitpid(pid, &status, 0) < 0)
      if (errno != EINTR) throw PlotError(fmt::format("waiting for '{}': {}", program, std::strerror(errno)));
    unregister_child(pid);
  }
  if (!WIFEXITED(status)) throw PlotError(fmt::format("'{}' was stopped by signal {}", program, WIFSIGNALED(status) ? WTERMSIG(status) : 0));
  return WEXITSTATUS(status);
}

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

void check_plot(const LinePlot& plot) {
  const InputLocation where{"", 0, "plot '" + plot.title + "'"};
  if (plot.series.empty()) throw InputError(where, "at least one series", "none");
  if (plot.width < 100 || plot.width > 10000 || plot.height < 100 || plot.height > 10000)
    throw InputError(where, "a size of 100 to 10000 pixels", fmt::format("{} x {}", plot.width, plot.height));
  for (const auto& [range, axis] : {std::pair{plot.x_range, "x"}, std::pair{plot.y_range, "y"}})
    if (range && !(std::isfinite((*range)[0]) && std::isfinite((*range)[1]) && (*range)[0] < (*range)[1]))
      throw InputError(where, fmt::format("a {} range [low, high] with low < high", axis), fmt::format("[{}, {}]", (*range)[0], (*range)[1]));
  for (const PlotSeries& s : plot.series) {
    const std::string which = "series '" + s.name + "'";
    if (s.x.size() != s.y.size()) throw InputError(where, "as many x as y values in " + which, fmt::format("{} x and {} y values", s.x.size(), s.y.size()));
    if (s.x.empty()) throw InputError(where, "values in " + which, "an empty series");
    if (s.segments && s.x.size() % 2 != 0)
      throw InputError(where, "an even number of points in " + which + " (drawn as segments, two points each)", fmt::format("{}", s.x.size()));
    for (std::size_t i = 0; i < s.x.size(); ++i)
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i]))
        throw InputError(where, "finite values in " + which, fmt::format("({}, {}) at point {}", s.x[i], s.y[i], i + 1));
    for (std::size_t i = 0; i < s.x.size(); ++i)
      if ((plot.log_x && !(s.x[i] > 0.0)) || (plot.log_y && !(s.y[i] > 0.0)))
        throw InputError(where, "positive values on a logarithmic axis in " + which, fmt::format("({}, {}) at point {}", s.x[i], s.y[i], i + 1));
  }
}

void check_figure(const PanelFigure& figure) {
  const InputLocation where{"", 0, "figure '" + figure.title + "'"};
  if (figure.rows < 1 || figure.columns < 1) throw InputError(where, "at least one row and one column of panels", fmt::format("{} x {}", figure.rows, figure.columns));
  if (figure.panels.empty() || figure.panels.size() > static_cast<std::size_t>(figure.rows * figure.columns))
    throw InputError(where, fmt::format("1 to {} panels", figure.rows * figure.columns), fmt::format("{}", figure.panels.size()));
  if (figure.width < 100 || figure.width > 10000 || figure.height < 100 || figure.height > 10000)
    throw InputError(where, "a size of 100 to 10000 pixels", fmt::format("{} x {}", figure.width, figure.height));
  for (const LinePlot& p : figure.panels) check_plot(p);
}

namespace {

std::string terminal_commands(int width, int height, const fs::path& png) {
  std::string s;
  // pngcairo draws anti-aliased lines; gnuplot-nox also has libgd's png.
  s += "if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {\n";
  s += fmt::format("  set terminal pngcairo size {},{} noenhanced font 'Sans,11' linewidth 1.2 background '#ffffff'\n", width, height);
  s += "} else {\n";
  s += fmt::format("  set terminal png size {},{} noenhanced background '#ffffff'\n", width, height);
  s += "}\n";
  s += "set encoding utf8\n";
  s += "set output " + quoted(fs::absolute(png).string()) + "\n";
  return s;
}

// The commands that draw one plot from the data file's blocks first_block,
// first_block + 1, ... (one per series). Every setting a previous panel of a
// multiplot may have changed is set again.
std::string plot_commands(const LinePlot& plot, const fs::path& data_file, std::size_t first_block) {
  std::string s;
  s += "set title " + quoted(plot.title) + " font ',13'\n";
  s += "set xlabel " + quoted(axis_title(plot.x_label, plot.x_unit)) + "\n";
  s += "set ylabel " + quoted(axis_title(plot.y_label, plot.y_unit)) + "\n";
  s += "set style line 100 lc rgb '#d0d0d0' lw 1 dt 1\n";
  s += "set grid xtics ytics linestyle 100, linestyle 100\n";
  s += "set border lw 1\n";
  if (plot.key) s += "set key below horizontal center Left reverse samplen 3 spacing 1.2 width 2\n";
  else s += "unset key\n";
  s += "set datafile separator ','\n";
  s += "set format y '%.6g'\n";
  s += "set format x '%.6g'\n";
  s += "unset logscale\n";
  if (plot.log_x) s += "set logscale x\nset mxtics 10\n";
  if (plot.log_y) s += "set logscale y\nset format y '%.3g'\n";
  s += plot.equal_axes ? "set size ratio -1\n" : "set size noratio\n";
  s += "set autoscale\n";
  if (plot.x_range) s += fmt::format("set xrange [{:.17g}:{:.17g}]\n", (*plot.x_range)[0], (*plot.x_range)[1]);
  if (plot.y_range) s += fmt::format("set yrange [{:.17g}:{:.17g}]\n", (*plot.y_range)[0], (*plot.y_range)[1]);
  if (plot.mark_points || plot.equal_axes) {
    // A little room so that the first and last markers (or a view's outer members) are not cut by the border.
    s += "set offsets graph 0.04, graph 0.04, graph 0.06, graph 0.06\n";
  } else {
    s += "set offsets 0, 0, 0, 0\n";
    s += "set autoscale xfix\n";
  }
  s += "plot ";
  for (std::size_t i = 0; i < plot.series.size(); ++i) {
    const PlotSeries& ser = plot.series[i];
    const std::size_t k = i % (sizeof(kColours) / sizeof(kColours[0]));
    const std::string colour = ser.colour.empty() ? std::string(kColours[k]) : ser.colour;
    if (i > 0) s += ", \\\n     ";
    s += fmt::format("{} index {} using 1:2", quoted(fs::absolute(data_file).string()), first_block + i);
    if (ser.points_only)
      s += fmt::format(" with points pt {} ps 1.1 lc rgb '{}'", kPointTypes[k], colour);
    else if (plot.mark_points)
      s += fmt::format(" with linespoints lw 2 pt {} ps 1.3 lc rgb '{}'", kPointTypes[k], colour);
    else
      s += fmt::format(" with lines lw 1.5 lc rgb '{}'", colour);
    s += ser.name.empty() ? std::string(" notitle") : " title " + quoted(ser.name);
  }
  s += "\n";
  return s;
}

// One block per series (gnuplot's "index"), blocks apart by two blank lines;
// a segments series has one blank line after each pair (a break in the line).
void write_series(std::ofstream& out, const std::vector<const PlotSeries*>& series) {
  for (std::size_t i = 0; i < series.size(); ++i) {
    const PlotSeries& ser = *series[i];
    out << (i > 0 ? "\n\n" : "") << "# " << ser.name << "\n";
    for (std::size_t p = 0; p < ser.x.size(); ++p) {
      out << fmt::format("{:.17g},{:.17g}\n", ser.x[p], ser.y[p]);
      if (ser.segments && p % 2 == 1 && p + 1 < ser.x.size()) out << "\n";
    }
  }
}

// Writes the data and the script into a scratch folder and runs gnuplot on it.
void render(const std::vector<const PlotSeries*>& series, const std::string& title, const std::function<std::string(const fs::path&)>& script_for,
            const fs::path& png, const std::string& gnuplot) {
  ScratchDir scratch;
  const fs::path data = scratch.path() / "plot.csv", script = scratch.path() / "plot.gp", log = scratch.path() / "gnuplot.log";
  auto gate = hold_output_gate();  // for the files below; released before gnuplot runs
  {
    std::ofstream out(data, std::ios::binary);
    write_series(out, series);
    out.close();
    if (!out) throw PlotError("cannot write the plot data " + data.string());
  }
  {
    std::ofstream out(script, std::ios::binary);
    out << script_for(data);
    out.close();
    if (!out) throw PlotError("cannot write the plot script " + script.string());
  }
  std::error_code ec;
  fs::remove(png, ec);
  gate.unlock();
  const int status = run_program(gnuplot, {script.string()}, log);
  std::string message = read_text(log);
  while (!message.empty() && (message.back() == '\n' || message.back() == ' ')) message.pop_back();
  if (status != 0) throw PlotError(fmt::format("gnuplot failed (exit status {}) drawing '{}': {}", status, title, message));
  if (!fs::exists(png, ec) || fs::file_size(png, ec) == 0)
    throw PlotError(fmt::format("gnuplot wrote no image {} for '{}': {}", png.string(), title, message));
}

}  // namespace

std::string gnuplot_script(const LinePlot& plot, const fs::path& data_file, const fs::path& png) {
  return "# framedyn line plot\n" + terminal_commands(plot.width, plot.height, png) + plot_commands(plot, data_file, 0) + "unset output\n";
}

std::string gnuplot_script(const PanelFigure& figure, const fs::path& data_file, const fs::path& png) {
  std::string s = "# framedyn figure of panels\n" + terminal_commands(figure.width, figure.height, png);
  s += fmt::format("set multiplot layout {},{} rowsfirst title {} font ',14'\n", figure.rows, figure.columns, quoted(figure.title));
  std::size_t block = 0;
  for (const LinePlot& p : figure.panels) {
    s += plot_commands(p, data_file, block);
    block += p.series.size();
  }
  s += "unset multiplot\nunset output\n";
  return s;
}

void write_png(const LinePlot& plot, const fs::path& png, const std::string& gnuplot) {
  check_plot(plot);
  std::vector<const PlotSeries*> series;
  for (const PlotSeries& s : plot.series) series.push_back(&s);
  render(series, plot.title, [&](const fs::path& data) { return gnuplot_script(plot, data, png); }, png, gnuplot);
}

void write_png(const PanelFigure& figure, const fs::path& png, const std::string& gnuplot) {
  check_figure(figure);
  std::vector<const PlotSeries*> series;
  for (const LinePlot& p : figure.panels)
    for (const PlotSeries& s : p.series) series.push_back(&s);
  render(series, figure.title, [&](const fs::path& data) { return gnuplot_script(figure, data, png); }, png, gnuplot);
}

bool gnuplot_available(const std::string& gnuplot) {
  try {
    ScratchDir scratch;
    return run_program(gnuplot, {"--version"}, scratch.path() / "version.log") == 0;
  } catch (const PlotError&) {
    return false;
  }
}

}  // namespace framedyn::report
