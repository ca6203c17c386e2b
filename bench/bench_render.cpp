// Frames per second of parksim's off-screen rendering on the study's head-in lot, with the robot
// driving along an arc and its executed path growing:
//   BM_Render/<view>/W/H      render and read back one frame (no file); view 0 top, 1 3D
//                             following the robot, 2 top as films draw it (the lot kept)
//   BM_Png/<png>/W/H          encode a film's rendered frames in turn: stb's deflate (png 3)
//                             against the frames' PngCompression: default (0, zlib level 1 in
//                             bands), fast (1), stored (2)
//   BM_PngLibrary/<lib>/W/H   the same frames through parksim's encoder (0 banded, 1 each frame
//                             alone, 2 fast) and through libspng (3 level 1, 4 defaults) and
//                             libdeflate (5 level 1): docs/rendering.md, "PNG: measured"
//   BM_Record/<view>/W/H/...  FrameRecorder end to end: render, encode on workers, write files
//                             (enc: encoder threads; fresh: new files, or rewriting the last
//                             iteration's, which this machine's ext4 does ten times faster;
//                             png: PngCompression, as in BM_Png)
// Run: build/bench/bench_render --benchmark_counters_tabular=true
// fps is frames per wall-clock second (llvmpipe and the encoder use threads); CPU is the whole
// process's CPU time, all threads, per iteration: on a busy machine fps drops, CPU time barely.

#include <benchmark/benchmark.h>
#include <libdeflate.h>
#include <spng.h>
#include <stb/stb_image.h>
#include <zlib.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "parksim/renders/film/FrameRecorder.h"
#include "parksim/renders/gl/Renderer.h"
#include "parksim/renders/image/PngEncoder.h"
#include "parksim/renders/scene/SceneBuilder.h"
#include "parksim/scenario/world/ScenarioReader.h"

namespace parksim {
namespace {

const Scenario& lot() {
  static const Scenario s = loadScenario(std::string(PARKSIM_SOURCE_DIR) + "/worlds/head_in.yaml");
  return s;
}

// The robot's pose at frame k: an arc through the lot, one lap every 600 frames.
Pose2 poseAt(int k) {
  const double a = 2.0 * 3.14159265358979 * (k % 600) / 600.0;
  return {0.9 + 0.6 * std::cos(a), 0.6 + 0.3 * std::sin(a), a + 1.5707963};
}

struct Episode {
  std::vector<Pose2> planned;
  std::vector<Pose2> executed;
  SceneStyle style;

  explicit Episode(int height) : style(SceneStyle{}.scaled(styleScaleFor(height))) {
    for (int k = 0; k < 600; k += 2) planned.push_back(poseAt(k));
  }

  SceneLayers nextLayers(int k) {
    executed.push_back(poseAt(k));
    if (executed.size() > 600) executed.erase(executed.begin());
    ViewState view;
    view.robot = poseAt(k);
    view.reference = poseAt(k + 1);
    view.planned_path = planned;
    view.executed_path = executed;
    view.overlay = Overlay{"head_in", k / 30.0, 0.0012, 0.004};
    return buildSceneLayers(lot(), view, style);
  }

  Scene next(int k) {
    SceneLayers layers = nextLayers(k);
    appendScene(layers.back, layers.front);
    return std::move(layers.back);
  }
};

CameraDef cameraFor(int view) { return view == 1 ? FrameDef{}.camera_3d : CameraDef{}; }

constexpr int kTopFilm = 2;  // BM_Render's top view drawn as films draw it: the lot kept

void BM_Render(benchmark::State& state) {
  const int view = static_cast<int>(state.range(0));
  RenderDef def;
  def.width_px = static_cast<int>(state.range(1));
  def.height_px = static_cast<int>(state.range(2));
  def.msaa_samples = static_cast<int>(state.range(3));
  Renderer renderer(def);
  Episode episode(def.height_px);
  RgbImage image(def.width_px, def.height_px);
  RgbaImage film_image(def.width_px, def.height_px);  // what a recorder reads back
  int k = 0;
  for (auto _ : state) {
    if (view == kTopFilm) {
      const SceneLayers layers = episode.nextLayers(k++);
      renderer.renderInto(layers.back, layers.front, CameraDef{}, film_image, 0);
      benchmark::DoNotOptimize(film_image.pixels.data());
    } else {
      renderer.render(episode.next(k++), cameraFor(view), image);
      benchmark::DoNotOptimize(image.pixels.data());
    }
  }
  state.counters["fps"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  static const char* const kViews[] = {"top", "3d-follow", "top, lot kept"};
  state.SetLabel(std::string(kViews[view]) + (def.msaa_samples > 1 ? " msaa" : ""));
}

constexpr int kStbPng = 3;  // BM_Png's stb_image_write with its own deflate, beside PngCompression

const char* pngLabel(int png) {
  return png == kStbPng ? "stb-default" : toString(static_cast<PngCompression>(png));
}

// Encodes a film: 30 successive frames in turn, RGBA, as a recorder's encoder sees them (the
// default copies the bands a frame shares with the one before).
void BM_Png(benchmark::State& state) {
  const int png = static_cast<int>(state.range(0));
  RenderDef def;
  def.width_px = static_cast<int>(state.range(1));
  def.height_px = static_cast<int>(state.range(2));
  Renderer renderer(def);
  Episode episode(def.height_px);
  std::vector<RgbaImage> film;
  std::vector<RgbImage> film_rgb;  // for stb, which takes RGB
  for (int k = 0; k < 30; ++k) {
    film.emplace_back(def.width_px, def.height_px);
    renderer.renderInto(episode.next(100 + k), CameraDef{}, film.back(), 0);
    film_rgb.push_back(film.back().rgb());
  }
  std::size_t bytes = 0;
  std::size_t k = 0;
  PngEncoder encoder(png == kStbPng ? PngCompression::kDefault : static_cast<PngCompression>(png));
  for (auto _ : state) {
    const std::size_t i = k++ % film.size();
    if (png == kStbPng) {
      const std::vector<unsigned char> out = encodePng(film_rgb[i], PngCompression::kSmall);
      bytes = out.size();
      benchmark::DoNotOptimize(out.data());
    } else {
      const std::span<const unsigned char> out = encoder.encode(film[i]);
      bytes = out.size();
      benchmark::DoNotOptimize(out.data());
    }
  }
  state.counters["fps"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["kB"] = static_cast<double>(bytes) / 1000.0;
  state.SetLabel(pngLabel(png));
}

// The PNG libraries beside parksim's own encoder (issue 40's decision, docs/rendering.md): the
// same film frames, RGBA as a recorder reads them back, each library given what it takes.
enum class PngLibrary {
  kOwnBanded,    // PngEncoder, kDefault: zlib level 1 in bands, unchanged bands copied
  kOwnWhole,     // the same encoder on each frame alone (encodePng: nothing kept)
  kOwnFast,      // PngEncoder, kFast (RunLengthDeflate.h), bands copied
  kSpngFast,     // libspng 0.7: filter none, zlib level 1
  kSpngDefault,  // libspng's defaults: adaptive filters, zlib's default level
  kLibdeflate1,  // libdeflate 1.14 level 1 over the filtered image, in a minimal container
};

const char* toString(PngLibrary library) {
  static const char* const kNames[] = {"own banded zlib-1", "own whole zlib-1",
                                       "own fast",          "libspng filter-none level-1",
                                       "libspng defaults",  "libdeflate level-1"};
  return kNames[static_cast<int>(library)];
}

std::vector<unsigned char> encodeSpng(const RgbImage& image, bool fast) {
  std::unique_ptr<spng_ctx, decltype(&spng_ctx_free)> ctx(spng_ctx_new(SPNG_CTX_ENCODER),
                                                          &spng_ctx_free);
  spng_set_option(ctx.get(), SPNG_ENCODE_TO_BUFFER, 1);
  if (fast) {
    spng_set_option(ctx.get(), SPNG_FILTER_CHOICE, SPNG_DISABLE_FILTERING);
    spng_set_option(ctx.get(), SPNG_IMG_COMPRESSION_LEVEL, 1);
  }
  spng_ihdr ihdr{};
  ihdr.width = static_cast<std::uint32_t>(image.width);
  ihdr.height = static_cast<std::uint32_t>(image.height);
  ihdr.bit_depth = 8;
  ihdr.color_type = SPNG_COLOR_TYPE_TRUECOLOR;
  spng_set_ihdr(ctx.get(), &ihdr);
  if (spng_encode_image(ctx.get(), image.pixels.data(), image.pixels.size(), SPNG_FMT_PNG,
                        SPNG_ENCODE_FINALIZE) != 0) {
    return {};
  }
  std::size_t size = 0;
  int error = 0;
  void* buffer = spng_get_png_buffer(ctx.get(), &size, &error);
  std::vector<unsigned char> out(static_cast<unsigned char*>(buffer),
                                 static_cast<unsigned char*>(buffer) + size);
  std::free(buffer);
  return out;
}

void putChunk(std::vector<unsigned char>& out, const char* tag, const unsigned char* data,
              std::size_t size) {
  auto put32 = [&](std::uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8)
      out.push_back(static_cast<unsigned char>(v >> shift));
  };
  put32(static_cast<std::uint32_t>(size));
  const std::size_t start = out.size();
  out.insert(out.end(), tag, tag + 4);
  out.insert(out.end(), data, data + size);
  put32(static_cast<std::uint32_t>(crc32(0, out.data() + start, static_cast<uInt>(size + 4))));
}

std::vector<unsigned char> encodeLibdeflate(const RgbImage& image, libdeflate_compressor* c,
                                            std::vector<unsigned char>& filtered,
                                            std::vector<unsigned char>& zdata) {
  const std::size_t row = static_cast<std::size_t>(image.width) * 3;
  filtered.resize((row + 1) * image.height);
  for (int y = 0; y < image.height; ++y) {
    filtered[y * (row + 1)] = 0;
    std::memcpy(&filtered[y * (row + 1) + 1], &image.pixels[y * row], row);
  }
  zdata.resize(libdeflate_zlib_compress_bound(c, filtered.size()));
  zdata.resize(
      libdeflate_zlib_compress(c, filtered.data(), filtered.size(), zdata.data(), zdata.size()));
  std::vector<unsigned char> out = {137, 80, 78, 71, 13, 10, 26, 10};
  unsigned char ihdr[13] = {};
  for (int i = 0; i < 4; ++i) {
    ihdr[i] = static_cast<unsigned char>(image.width >> (24 - 8 * i));
    ihdr[4 + i] = static_cast<unsigned char>(image.height >> (24 - 8 * i));
  }
  ihdr[8] = 8;  // bit depth
  ihdr[9] = 2;  // truecolour
  putChunk(out, "IHDR", ihdr, sizeof ihdr);
  putChunk(out, "IDAT", zdata.data(), zdata.size());
  putChunk(out, "IEND", nullptr, 0);
  return out;
}

bool decodesTo(std::span<const unsigned char> png, const RgbImage& image) {
  int w = 0, h = 0, n = 0;
  unsigned char* pixels =
      stbi_load_from_memory(png.data(), static_cast<int>(png.size()), &w, &h, &n, 3);
  const bool same = pixels != nullptr && w == image.width && h == image.height &&
                    std::memcmp(pixels, image.pixels.data(), image.pixels.size()) == 0;
  stbi_image_free(pixels);
  return same;
}

// Encodes a film's 30 successive frames in turn, as BM_Png; every library's files are first
// decoded and checked to hold the frame's pixels (else the benchmark reports an error).
void BM_PngLibrary(benchmark::State& state) {
  const auto library = static_cast<PngLibrary>(state.range(0));
  RenderDef def;
  def.width_px = static_cast<int>(state.range(1));
  def.height_px = static_cast<int>(state.range(2));
  Renderer renderer(def);
  Episode episode(def.height_px);
  std::vector<RgbaImage> film;
  for (int k = 0; k < 30; ++k) {
    film.emplace_back(def.width_px, def.height_px);
    const SceneLayers layers = episode.nextLayers(100 + k);
    renderer.renderInto(layers.back, layers.front, CameraDef{}, film.back(), 0);
  }
  PngEncoder banded(library == PngLibrary::kOwnFast ? PngCompression::kFast
                                                    : PngCompression::kDefault);
  std::unique_ptr<libdeflate_compressor, decltype(&libdeflate_free_compressor)> compressor(
      libdeflate_alloc_compressor(1), &libdeflate_free_compressor);
  std::vector<unsigned char> filtered, zdata, file;
  // RGBA in, the PNG's bytes out: the conversion to RGB counts, as a recorder needs it.
  auto encode = [&](const RgbaImage& frame) -> std::span<const unsigned char> {
    switch (library) {
      case PngLibrary::kOwnBanded:
      case PngLibrary::kOwnFast: return banded.encode(frame);
      case PngLibrary::kOwnWhole: file = encodePng(frame.rgb()); return file;
      case PngLibrary::kSpngFast:
      case PngLibrary::kSpngDefault:
        file = encodeSpng(frame.rgb(), library == PngLibrary::kSpngFast);
        return file;
      case PngLibrary::kLibdeflate1:
        file = encodeLibdeflate(frame.rgb(), compressor.get(), filtered, zdata);
        return file;
    }
    return {};
  };
  for (const RgbaImage& frame : film) {
    if (!decodesTo(encode(frame), frame.rgb())) {
      state.SkipWithError("a file does not decode to its frame");
      return;
    }
  }
  std::size_t bytes = 0;
  std::size_t k = 0;
  for (auto _ : state) {
    const std::span<const unsigned char> out = encode(film[k++ % film.size()]);
    bytes = out.size();
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["fps"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["kB"] = static_cast<double>(bytes) / 1000.0;
  state.SetLabel(toString(library));
}

void BM_Record(benchmark::State& state) {
  constexpr int kFramesPerIteration = 200;
  const auto view = static_cast<FrameView>(state.range(0));
  FrameDef def;
  def.width_px = static_cast<int>(state.range(1));
  def.height_px = static_cast<int>(state.range(2));
  def.view = view;
  def.msaa_samples = static_cast<int>(state.range(3));
  def.encode_threads = static_cast<int>(state.range(4));
  const bool fresh = state.range(5) != 0;
  def.png_compression = static_cast<PngCompression>(state.range(6));
  def.fps = 30.0;
  def.out_dir = (std::filesystem::temp_directory_path() / "parksim_bench_render").string();
  Trajectory plan;
  for (int k = 0; k < 600; k += 10) plan.points.push_back({k / 30.0, poseAt(k), {}});
  auto sample = [&](int k) {
    FrameInput in;
    in.t_s = k / def.fps;
    in.pose = poseAt(k);
    in.reference = poseAt(k + 1);
    return in;
  };
  for (auto _ : state) {
    // Once per episode, not timed: context creation, directory cleanup, and the first frame,
    // whose draws make llvmpipe compile its shader variants (see BM_FirstFrame).
    state.PauseTiming();
    if (fresh) std::filesystem::remove_all(def.out_dir);
    auto rec = std::make_unique<FrameRecorder>(lot(), def);
    rec->setPlan(plan);
    rec->addFrame(sample(0));
    state.ResumeTiming();
    for (int k = 1; k <= kFramesPerIteration; ++k) rec->addFrame(sample(k));
    rec->finish();  // waits for the last files
    state.PauseTiming();
    rec.reset();
    state.ResumeTiming();
  }
  state.counters["fps"] = benchmark::Counter(
      static_cast<double>(state.iterations()) * kFramesPerIteration, benchmark::Counter::kIsRate);
  state.SetLabel(std::string(toString(view)) + (def.msaa_samples > 1 ? " msaa" : "") +
                 (fresh ? " new-files " : " rewrite ") + toString(def.png_compression));
  std::filesystem::remove_all(def.out_dir);
}

// Setting up a recorder: GL context, framebuffers, font atlas, and the first frame, during
// which llvmpipe compiles the shaders for this context.
void BM_FirstFrame(benchmark::State& state) {
  FrameDef def;
  def.out_dir = (std::filesystem::temp_directory_path() / "parksim_bench_first").string();
  for (auto _ : state) {
    FrameRecorder rec(lot(), def);
    FrameInput in;
    in.pose = poseAt(0);
    rec.addFrame(in);
    rec.finish();
  }
  std::filesystem::remove_all(def.out_dir);
}

BENCHMARK(BM_Render)
    ->ArgNames({"view", "w", "h", "msaa"})
    ->Args({0, 640, 480, 1})
    ->Args({kTopFilm, 640, 480, 1})
    ->Args({0, 640, 480, 4})
    ->Args({0, 1280, 720, 1})
    ->Args({0, 1280, 720, 4})
    ->Args({1, 640, 480, 1})
    ->Args({1, 640, 480, 4})
    ->MeasureProcessCPUTime()
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Png)
    ->ArgNames({"png", "w", "h"})
    ->ArgsProduct({{kStbPng, 0, 1, 2}, {640}, {480}})
    ->ArgsProduct({{kStbPng, 0, 1, 2}, {1280}, {720}})
    ->MeasureProcessCPUTime()
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PngLibrary)
    ->ArgNames({"lib", "w", "h"})
    ->ArgsProduct({{0, 1, 2, 3, 4, 5}, {640}, {480}})
    ->ArgsProduct({{0, 1, 2, 3, 4, 5}, {1280}, {720}})
    ->MeasureProcessCPUTime()
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FirstFrame)->MeasureProcessCPUTime()->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Record)
    ->ArgNames({"view", "w", "h", "msaa", "enc", "fresh", "png"})
    ->Args({static_cast<int>(FrameView::kTop), 640, 480, 1, 1, 1, 0})
    ->Args({static_cast<int>(FrameView::kTop), 640, 480, 1, 1, 1, 1})
    ->Args({static_cast<int>(FrameView::kTop), 640, 480, 1, 1, 1, 2})
    ->Args({static_cast<int>(FrameView::kTop), 640, 480, 1, 2, 1, 0})
    ->Args({static_cast<int>(FrameView::kTop), 640, 480, 1, 1, 0, 0})
    ->Args({static_cast<int>(FrameView::kTop), 640, 480, 1, 2, 0, 0})
    ->Args({static_cast<int>(FrameView::kTop), 640, 480, 4, 1, 1, 0})
    ->Args({static_cast<int>(FrameView::kTop), 1280, 720, 1, 1, 1, 0})
    ->Args({static_cast<int>(FrameView::kTop), 1280, 720, 4, 1, 1, 0})
    ->Args({static_cast<int>(FrameView::k3d), 640, 480, 1, 1, 1, 0})
    ->Args({static_cast<int>(FrameView::kBoth), 640, 480, 1, 1, 1, 0})
    ->Args({static_cast<int>(FrameView::kBoth), 640, 480, 1, 1, 1, 1})
    ->MeasureProcessCPUTime()
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace parksim
