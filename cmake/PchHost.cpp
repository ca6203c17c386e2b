// The source of the library that carries parksim's shared precompiled header for libraries
// (cmake/TargetDefaults.cmake). The header is what it is for; this file is only here because a
// target needs a source.
