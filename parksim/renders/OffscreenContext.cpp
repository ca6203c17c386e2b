#include "parksim/renders/OffscreenContext.h"

#include "parksim/core/Error.h"
#include "parksim/renders/OsMesaContext.h"

namespace parksim {

std::unique_ptr<OffscreenContext> createOffscreenContext(const ContextDef& def) {
  switch (def.backend) {
    case ContextBackend::kOsMesa: return detail::createOsMesaContext(def);
  }
  throw Error("offscreen context: unknown backend");
}

}  // namespace parksim
