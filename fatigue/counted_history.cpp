// A history's cycles and damage in one pass; see counted_history.h.
#include "fatigue/counted_history.h"

#include "fatigue/miner_damage.h"

namespace framedyn::fatigue {

namespace {

// Passes each cycle to the list and, with a curve, to the damage sum.
class Tee : public CycleSink {
 public:
  Tee(CycleSink& a, CycleSink* b) : a_(a), b_(b) {}
  void add(double range, double mean, double count) override {
    a_.add(range, mean, count);
    if (b_) b_->add(range, mean, count);
  }

 private:
  CycleSink& a_;
  CycleSink* b_;
};

}  // namespace

CountedHistory count_history(const std::vector<double>& history, Residue residue, const std::optional<SnCurve>& curve,
                             double pascals_per_unit) {
  CountedHistory out;
  CycleList list;
  std::optional<MinerDamage> damage;
  if (curve) damage.emplace(*curve, pascals_per_unit);  // as-welded: no mean-stress correction
  Tee tee(list, damage ? &*damage : nullptr);
  out.summary = count_cycles(history, residue, tee);
  out.cycles = std::move(list.cycles);
  if (curve) {
    out.damage = damage->damage();
    if (const std::optional<double> eq = equivalent_range(*curve, *out.damage)) out.equivalent_range = *eq / pascals_per_unit;
  }
  return out;
}

}  // namespace framedyn::fatigue
