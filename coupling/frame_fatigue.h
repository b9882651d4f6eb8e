// Fatigue life of the frame (docs/theory/fatigue.md, sections 7-9, Eqs. F.20-F.25): at
// every stress station and section point of the element-set outputs, the total normal
// stress (static + dynamic, coupling/hot_spots.h) over the steady window is rainflow-
// counted as a repeated block (ASTM E1049, fatigue/rainflow.h), its Palmgren-Miner damage
// taken on the S-N curve of the station's element set (a FAT class of IIW 2016 or a
// detail category of EN 1993-1-9, fatigue/sn_curve.h), and scaled from the window to an
// hour (F.20): d_h = D_window * 3600 s / T_block, the life L = 1 / d_h hours (F.21).
// Which stress: the normal stress range of the section point (details loaded normal to
// the weld toe, IIW §3.2 / EN 1993-1-9 Table 8.1-8.5) on the detail's normal-stress curve,
// and the signed shear stress along the point's wall (torsion + transverse shear,
// fem::signed_shear, F.26) on the code's shear curve (IIW FAT80/100 m = 5; EN 1993-1-9
// delta tau_C, m = 5, cut-off at 1e8), combined as the code says (section 10, F.27-F.29):
// IIW Gough-Pollard on the damage sums with CV = 1.0 where sigma(t) and tau(t) are
// proportional and 0.5 where they are not (section 12, F.32-F.33: proportional when the
// correlation of the two histories over the steady window has |r| >= 0.95), the smaller
// stress neglected when its largest range is under 15 % of the other's; EN 1993-1-9 the
// sum of the two damage ratios. The life map and the life use the combined damage; the
// damage under both CVs is kept at every point.
//
// A duty cycle (F.23-F.25): scenarios i with hours H_i, each a life map per hour d_h,i;
// the damage over the cycle D = sum_i H_i d_h,i (Miner: damage adds), the life in
// cycles 1 / D and in hours sum_i H_i / D; the scenario with the largest H_i d_h,i
// dominates a location (the lowest scenario index among those within 1e-6 relative).
//
// The study key (frame.fatigue / frame_response.fatigue, docs/user-guide.md "Fatigue"):
//   fatigue:
//     code: IIW                     # IIW (2016) | EN1993 (EN 1993-1-9)
//     default: FAT71                # FAT class / detail category of sets not listed (MPa)
//     shear_default: FAT80          # shear FAT class / delta tau_C of sets not listed (MPa)
//     details: [{element_set: LEFT_RAIL, class: FAT80, shear_class: FAT100}]   # first listed set holding an element wins;
//                                   # curve: FILE.yaml (an S-N curve file, relative to the study) instead of class
//     mean_stress: none             # none (as-welded) | goodman (with ultimate_strength)
//     ultimate_strength: 58000      # stress, Goodman only
//     thickness: 0.5                # length: wall thickness for the thickness correction (none at <= 25 mm)
//     thickness_exponent: 0.3       # IIW n (EN 1993-1-9 uses 0.2)
//     hours: 1000                   # h: the damage reported is over this many hours
#pragma once

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "core/error.h"
#include "coupling/hot_spots.h"
#include "coupling/yaml_input.h"
#include "fatigue/mean_stress.h"
#include "fatigue/sn_curve.h"
#include "fem/frame_model.h"

namespace framedyn::coupling {

enum class FatigueCode { iiw, en1993 };

struct FatigueDetail {
  std::string element_set;     // as the study spells it (mesh sets are matched case-insensitively)
  double class_mpa = 71.0;     // FAT class / detail category: the normal stress range at 2e6 cycles, MPa
  std::optional<double> shear_class_mpa;  // the shear range at 2e6 cycles, MPa; nullopt: the request's shear default
  core::InputLocation where = {};  // for messages about the set
  // A user curve from an S-N curve file (details[i].curve, coupling/sn_curve_file.h) instead of
  // class_mpa: used as it is (no thickness correction: the file's curve holds its own).
  std::optional<fatigue::SnCurve> curve = std::nullopt;
};

struct FatigueRequest {
  FatigueCode code = FatigueCode::iiw;
  double default_class_mpa = 71.0;
  double shear_default_class_mpa = 80.0;  // IIW FAT80 (fillet weld throat) / EN 1993-1-9 delta tau_C 80
  std::vector<FatigueDetail> details;
  fatigue::MeanStressCorrection mean_stress = fatigue::MeanStressCorrection::none();
  std::optional<double> thickness;  // m
  double thickness_exponent = 0.3;  // IIW n
  double hours = 1.0;               // h
  core::InputLocation where;        // the block, for messages
};

// The `fatigue` map (STUDY-114 .. STUDY-119).
FatigueRequest read_fatigue_block(const YamlMap& block);
// The S-N curve of a class under the request's code and thickness correction.
fatigue::SnCurve fatigue_curve(const FatigueRequest& request, double class_mpa);
// The code's shear S-N curve of a class (no thickness correction: both codes apply it to normal stress).
fatigue::SnCurve fatigue_shear_curve(const FatigueRequest& request, double class_mpa);

// IIW's comparison values CV for normal and shear stress of steel (IIW 2016, combined normal
// and shear stress): 1.0 when they are proportional, 0.5 when they are not.
inline constexpr double kIiwProportionalComparisonValue = 1.0;
inline constexpr double kIiwNonProportionalComparisonValue = 0.5;
// sigma(t) and tau(t) count as proportional where their correlation has |r| at least this
// (F.33; a sine pair shifted by phi has r = cos phi: 0.95 admits |phi| <= 18.2 degrees).
inline constexpr double kProportionalCorrelation = 0.95;
// The correlation coefficient r of two histories of the same length (F.32); 1 when either
// does not vary (a single varying stress is proportional to nothing but itself).
double stress_correlation(const std::vector<double>& sigma, const std::vector<double>& tau);
// The CV the IIW combination applies at a point of correlation r (F.33).
inline double iiw_comparison_value(double correlation) {
  return std::abs(correlation) >= kProportionalCorrelation ? kIiwProportionalComparisonValue : kIiwNonProportionalComparisonValue;
}
// IIW: a stress whose largest range is under this fraction of the other's is neglected.
inline constexpr double kIiwNeglectFraction = 0.15;
// The combined damage of a normal and a shear damage sum over the same period (F.27-F.29):
// the period over the life the combination allows. IIW: the number of periods k at which
// (D_s k)^(2/3) + (D_t k)^(2/5) = CV, returned as 1 / k, or the one sum alone when the other
// stress's largest range is under 15 % of its own; EN 1993-1-9: D_s + D_t. Ranges in Pa.
double combined_damage(FatigueCode code, double normal_damage, double shear_damage, double normal_max_range, double shear_max_range,
                       double comparison_value = kIiwNonProportionalComparisonValue);
// How the combination is taken, for reports; and how proportionality is measured.
std::string combination_rule(FatigueCode code);
std::string proportionality_rule(FatigueCode code);
// "IIW 2016 (Hobbacher, IIW-2259-15)" or "EN 1993-1-9:2005".
std::string fatigue_code_name(FatigueCode code);

// Damage per hour and life at every station and section point.
struct LifeMap {
  std::string code;                       // the code's full name
  FatigueCode code_id = FatigueCode::iiw;
  double block_seconds = 0.0;             // T_block: the steady window as a repeated block (n samples x dt)
  std::size_t block_samples = 0;
  std::vector<int> curve_of_station;      // index into curves, per StressHistories station
  std::vector<std::string> curves;        // curve names (SnCurve::name), in first use order
  std::vector<std::string> shear_curves;  // per curve: the shear curve's name
  std::vector<std::string> assignment;    // per curve: "LEFT_RAIL (details[0])" / "default" ...
  // Per station s, per section point p of its section: damage per hour (1/h), normal and shear
  // combined (F.27-F.29); the normal-only and shear-only parts; each stress's largest
  // counted range (Pa, the 15 % rule). An open wall's shear is that of its worse face.
  std::vector<std::vector<double>> damage_per_hour;
  std::vector<std::vector<double>> normal_damage_per_hour, shear_damage_per_hour;
  std::vector<std::vector<double>> normal_max_range, shear_max_range;
  // Proportionality (F.32, F.33): the correlation r of sigma(t) and tau(t) (the face whose
  // shear damage is kept), the CV applied, and the damage per hour under each IIW CV
  // (both equal to damage_per_hour under EN 1993-1-9, which has no CV).
  std::vector<std::vector<double>> correlation, comparison_value;
  std::vector<std::vector<double>> proportional_damage_per_hour, non_proportional_damage_per_hour;
  // The location of the largest damage per hour (ties to the lowest station, then point).
  std::size_t worst_station = 0;
  int worst_point = 0;
  double max_damage_per_hour() const;
};

// The life map of one run. Throws core::InputError (STUDY-120) for a details set the mesh
// lacks or whose elements no output station lies on.
// `share`: idle workers of a pool may take stations (the same map without).
LifeMap frame_life_map(const fem::FrameModel& model, const StressHistories& histories, const std::vector<fem::SectionForces>& static_forces,
                       const SteadyWindow& window, const FatigueRequest& request, core::WorkShare* share = nullptr);

// The damage of one stress history (Pa) rainflow-counted as a repeated block on `curve`:
// what the life map does at every point, exposed so a test can apply fatigue/ by hand.
double repeated_block_damage(const std::vector<double>& stress_pa, const fatigue::SnCurve& curve, const fatigue::MeanStressCorrection& mean_stress);

// A duty cycle's life: scenarios' life maps (same stations and points) with their hours.
struct DutyScenario {
  std::string name;
  double hours = 0.0;
  const LifeMap* map = nullptr;
};
struct DutyLife {
  double cycle_hours = 0.0;                           // sum H_i
  std::vector<std::vector<double>> damage_per_cycle;  // D per station and point (F.23), normal and shear combined (F.29)
  std::vector<std::vector<double>> normal_damage_per_cycle, shear_damage_per_cycle;  // sum H_i d_h,i of each stress
  std::vector<std::vector<int>> dominant;             // the scenario index doing most (combined) damage there
  // Proportionality over the cycle (F.34): the correlation of the least proportional scenario
  // doing damage there, the CV applied, and the cycle's damage under each IIW CV.
  std::vector<std::vector<double>> correlation, comparison_value;
  std::vector<std::vector<double>> proportional_damage_per_cycle, non_proportional_damage_per_cycle;
  std::size_t worst_station = 0;
  int worst_point = 0;
  // Life in hours of the duty cycle at a location: cycle_hours / D (infinite for D = 0).
  double life_hours(std::size_t station, int point) const;
};
// Throws std::invalid_argument when the maps do not have the same stations and points.
DutyLife combine_duty_cycle(const std::vector<DutyScenario>& scenarios);

// The worst location of a per-station-and-point table (largest value; ties within 1e-6
// relative to the lowest station, then the lowest point).
std::pair<std::size_t, int> worst_location(const std::vector<std::vector<double>>& values);

}  // namespace framedyn::coupling
