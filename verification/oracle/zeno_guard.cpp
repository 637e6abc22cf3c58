#include "verification/oracle/zeno_guard.hpp"

#include <string>

namespace gp::verification {

ZenoGuard::ZenoGuard(const OracleOptions& options)
    : max_events_(options.max_events),
      zeno_events_(options.zeno_events),
      zeno_window_(options.zeno_window) {}

void ZenoGuard::record(double t, const std::string& bodies) {
  if (++count_ > max_events_) {
    throw OracleDomainError("more than " + std::to_string(max_events_) + " impacts (the last of " +
                                bodies + "): a Zeno sequence or a scene too busy for the oracle",
                            t);
  }
  recent_.push_back(t);
  if (recent_.size() > zeno_events_) recent_.pop_front();
  if (recent_.size() == zeno_events_ && t - recent_.front() <= zeno_window_) {
    throw OracleDomainError(std::to_string(zeno_events_) + " impacts within " +
                                message_number(t - recent_.front()) + " s (the last of " + bodies +
                                "): a Zeno sequence, resting contact in the limit",
                            t);
  }
}

}  // namespace gp::verification
