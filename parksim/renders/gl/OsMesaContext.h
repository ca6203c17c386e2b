#pragma once
// Internal to parksim_render: the OSMesa backend of OffscreenContext (compiled only when
// pkg-config finds osmesa; Mesa 25.1 and later have none).

#include <memory>

#include "parksim/renders/gl/OffscreenContext.h"

namespace parksim::detail {

std::unique_ptr<OffscreenContext> createOsMesaContext(const ContextDef& def);

}  // namespace parksim::detail
