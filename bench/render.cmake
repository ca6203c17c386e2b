# Rendering benchmark: frames per second for rendering alone, PNG encoding alone (stb's deflate
# against the zlib route, side by side) and the frame recorder end to end (docs/rendering.md).
include_guard(GLOBAL)
add_executable(bench_render ${CMAKE_CURRENT_LIST_DIR}/bench_render.cpp)
target_link_libraries(bench_render PRIVATE parksim_render parksim_scenario benchmark::benchmark
                                           benchmark::benchmark_main)
target_compile_definitions(bench_render PRIVATE PARKSIM_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
parksim_target_defaults(bench_render)
# libspng and libdeflate only for BM_PngLibrary: the PNG libraries measured beside the
# encoder parksim keeps (docs/rendering.md, "PNG: measured, then decided").
find_package(PkgConfig REQUIRED)
pkg_check_modules(PARKSIM_SPNG REQUIRED IMPORTED_TARGET spng)
target_link_libraries(bench_render PRIVATE PkgConfig::PARKSIM_SPNG PkgConfig::LIBDEFLATE ZLIB::ZLIB
                                           parksim::stb)
