#include "verification/oracle/zeno_guard.hpp"

#include <string>

namespace gp::oracle {

using verification::message_number;
using verification::OracleDomainError;
using verification::OracleOptions;

ZenoGuard::ZenoGuard(const OracleOptions& options)
    : max_events_(options.max_events),
      zeno_events_(options.zeno_events),
      zeno_window_(options.zeno_window) {}

void ZenoGuard::record(double t, const std::string& what) {
  if (++count_ > max_events_) {
    throw OracleDomainError("more than " + std::to_string(max_events_) + " events (the last " +
                                what + "): a Zeno sequence or a scene too busy for the oracle",
                            t);
  }
  recent_.push_back(t);
  if (recent_.size() > zeno_events_) recent_.pop_front();
  if (recent_.size() == zeno_events_ && t - recent_.front() <= zeno_window_) {
    throw OracleDomainError(std::to_string(zeno_events_) + " events within " +
                                message_number(t - recent_.front()) + " s (the last " + what +
                                "): a Zeno sequence the rest speed did not end",
                            t);
  }
}

}  // namespace gp::oracle
