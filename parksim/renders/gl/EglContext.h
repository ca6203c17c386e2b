#pragma once
// Internal to parksim_render: the EGL backend of OffscreenContext. EGL 1.5 without a surface
// (EGL_KHR_surfaceless_context, EGL_KHR_no_config_context) on Mesa's software device
// (EGL_MESA_device_software: llvmpipe, as OSMesa draws), or on Mesa's surfaceless platform when
// no software device is listed.

#include <memory>

#include "parksim/renders/gl/OffscreenContext.h"

namespace parksim::detail {

std::unique_ptr<OffscreenContext> createEglContext(const ContextDef& def);

}  // namespace parksim::detail
