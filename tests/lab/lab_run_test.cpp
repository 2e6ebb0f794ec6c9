// snell-lab end to end (the GL passes on llvmpipe, the ray tracer, the CPU
// mirror, the table) on the sphere-in-front-of-a-painting scene at 64x64, and
// the command line's errors and exit codes.
#include "lab_run.hpp"
#include "references.hpp"
#include "technique.hpp"

#include "lab/metrics.hpp"
#include "lab/tracer.hpp"

#include "lab_run_util.hpp"

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;
using snell::lab::LabOptions;
using snell::lab::LabResult;
using snell::lab::TechniqueRow;

LabOptions options64(const std::string& out) {
  LabOptions o = labtest::labRunOptions("sphere_painting", 64);
  o.frames = 3;
  o.outDir = out;
  return o;
}

TEST(LabRun, SphereSceneEndToEnd) {
  labtest::TempDir dir;
  const LabResult r = snell::lab::runLab(options64(dir.file("out")));
  ASSERT_EQ(r.rows.size(), snell::snellTechniqueTable().size() + snell::snellEngineModelTable().size());
  EXPECT_EQ(r.width, 64);
  EXPECT_GT(r.objectPixels, 400u);
  for (const TechniqueRow& t : r.rows) {
    SCOPED_TRACE(t.name);
    std::printf("[lab] %-15s mse %.4g (two %.4g) invalid %.3f fetches %.1f cost %.2fx cpu-gpu max %.2f/255 >1/255 %.4f%%\n",
                t.name.c_str(), t.mseFull, t.mseTwo, t.invalidShare, t.fetchesPerPixel, t.costRatio,
                255.0 * t.cpuGpuMaxAbs, 100.0 * t.cpuGpuBeyond1);
    EXPECT_TRUE(std::isfinite(t.mseFull));
    // Against the full and the two-interface references over the same pixels, a row's RMS errors differ by at
    // most the references' own RMS difference (the triangle inequality): a row scored on another image, mask or
    // reference breaks it.
    EXPECT_LE(std::abs(std::sqrt(t.mseFull) - std::sqrt(t.mseTwo)), std::sqrt(r.mseTwoVsFull) + 1e-9);
    EXPECT_GE(t.fetchesPerPixel, 1.0);
    EXPECT_GT(t.medianMs, 0.0);
    EXPECT_GT(t.costRatio, 0.0);
    // The issue's parity criterion: 99.9 % of pixels within 1/255, none beyond 4/255 but rounding ties
    // (a texel or TIR boundary that last-bit differences put on opposite sides: the 512-step march of the
    // image-space bound meets one on this 64x64 frame).
    EXPECT_LE(t.cpuGpuBeyond1, 0.001);
    EXPECT_EQ(t.cpuGpuBeyond4Pixels, t.cpuGpuBeyond4Ties);
    // An engine row runs the sweep's best value, and its GPU image scores what the C++ sweep measured for it.
    if (t.engine != nullptr) {
      ASSERT_GE(t.engineSweep.size(), 41u);
      double best = t.engineSweep.front().second;
      for (const auto& tried : t.engineSweep) best = std::min(best, tried.second);
      EXPECT_NEAR(t.mseFull, best, 0.02 * best + 1e-6);
    } else {
      EXPECT_TRUE(t.engineSweep.empty());
    }
  }
  const TechniqueRow* single = r.row("single");
  const TechniqueRow* plane = r.row("plane-normal-1");
  const TechniqueRow* bound = r.row("image-space-bound");
  ASSERT_NE(bound, nullptr);
  EXPECT_EQ(bound->mseBound, 0.0);
  EXPECT_DOUBLE_EQ(bound->boundRatio, 1.0);
  // The bound intersects the same buffers better than one sample or a short march can.
  EXPECT_GT(single->boundRatio, 1.0);
  EXPECT_GT(r.row("linear-march")->boundRatio, 1.0);
  EXPECT_NEAR(r.boundInformationMse + r.boundBufferMse, bound->mseTwo, 1e-9);
  // The bounce rows are measured against the bound with bounces, on the model they follow (the principal
  // path of 2 + 4 events); the two-interface rows on theirs.
  const TechniqueRow* bounceBound = r.row("image-space-bound-bounces");
  ASSERT_NE(bounceBound, nullptr);
  EXPECT_EQ(bounceBound->mseBound, 0.0);
  EXPECT_DOUBLE_EQ(bounceBound->boundRatio, 1.0);
  EXPECT_EQ(bounceBound->modelEvents, 6);
  EXPECT_EQ(r.row("plane-normal-2-bounces")->bounces, 4);
  EXPECT_EQ(single->modelEvents, 2);
  EXPECT_EQ(single->mseModel, single->mseTwo);
  for (const TechniqueRow& t : r.rows) EXPECT_EQ(t.unshadedShare, 0.0) << t.name;  // the whole sphere is in view
  ASSERT_NE(single, nullptr);
  ASSERT_NE(plane, nullptr);
  EXPECT_DOUBLE_EQ(single->costRatio, 1.0);
  EXPECT_EQ(single->invalidShare, 0.0);  // one sample always finds a surface behind
  // The point of the plane method (Mayer & Assarsson): better than one sample.
  EXPECT_GT(single->mseFull, plane->mseFull);
  // The two-interface model is close to the full ray tracer on a sphere (no TIR from the camera).
  EXPECT_LT(r.mseTwoVsFull, 0.01);
  // Nor inside: a chord of a sphere meets the surface at its entry angle, below the critical angle, so
  // (but for grazing pixels of the tessellated sphere) no pixel meets TIR and following more interface
  // events changes nothing.
  EXPECT_LT(r.tirShare, 0.01);
  ASSERT_EQ(r.modelFloors.size(), 3u);
  for (const snell::lab::ModelFloor& f : r.modelFloors) EXPECT_NEAR(f.mseFull, r.mseTwoVsFull, 1e-4) << f.events;
  EXPECT_EQ(r.modelFloors[0].events, 3);
  for (const char* f : {"table.md", "table.json", "overview.png", "ground_truth.png", "reference_two_interfaces.png",
                        "single.png", "plane-normal-1.png", "dda.png"})
    EXPECT_TRUE(fs::exists(dir.file("out") + "/" + f)) << f;
  std::ifstream md(dir.file("out") + "/table.md");
  std::stringstream text;
  text << md.rdbuf();
  EXPECT_NE(text.str().find("| single sample |"), std::string::npos);
}

TEST(LabRun, EglBackendAgreesWithTheDefault) {
  LabOptions o = options64("");
  o.techniques = {"single", "plane-normal-1"};
  o.frames = 1;
  const LabResult a = snell::lab::runLab(o);
  o.backend = "egl";
  const LabResult b = snell::lab::runLab(o);
  // The two asked for, and the image-space bound the others are measured against.
  ASSERT_EQ(a.rows.size(), 3u);
  ASSERT_EQ(b.rows.size(), 3u);
  EXPECT_EQ(a.rows[2].name, "image-space-bound");
  EXPECT_NE(b.gpu.find("egl"), std::string::npos);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(a.rows[i].mseFull, b.rows[i].mseFull, 1e-6) << a.rows[i].name;
    EXPECT_EQ(b.rows[i].cpuGpuBeyond4Pixels, b.rows[i].cpuGpuBeyond4Ties) << b.rows[i].name;
  }
}

// A technique that bounces brings the bound with its bounces; the two-interface bound runs as always.
TEST(LabRun, ABounceTechniqueIsMeasuredAgainstTheBoundWithBounces) {
  LabOptions o = options64("");
  o.techniques = {"plane-normal-2-bounces"};
  o.frames = 1;
  const LabResult r = snell::lab::runLab(o);
  ASSERT_EQ(r.rows.size(), 3u);
  EXPECT_EQ(r.rows[0].name, "image-space-bound");
  EXPECT_EQ(r.rows[1].name, "plane-normal-2-bounces");
  EXPECT_EQ(r.rows[2].name, "image-space-bound-bounces");
  EXPECT_EQ(r.rows[1].modelEvents, 6);
  EXPECT_EQ(r.boundRow(), &r.rows[0]);
  // Its own error is against the bound with bounces, not the two-interface one.
  EXPECT_GT(r.rows[1].mseBound, 0.0);
  EXPECT_DOUBLE_EQ(r.rows[1].boundRatio, r.rows[1].mseModel / r.rows[2].mseModel);
}

// A dispersive ball (n_d 1.6, V_d 20) before a checker card: the rows follow one path per colour channel as
// the ray tracer does. Drawn with one path for all three, a row would add the dispersion itself to its own
// error (the two-interface model's picture with each channel's IOR against that with the d line's for all,
// three times the rows' error on the same ball without dispersion at this size, where the truth's single
// ray per pixel against the rows' filtered card reads dominates it).
TEST(LabRun, ADispersiveObjectIsDrawnWithAPathPerChannel) {
  labtest::TempDir dir;
  const std::string ball = R"({
    "camera": { "position": [0, 0, 5], "fov": 40 },
    "object": { "mesh": { "type": "icosphere", "radius": 1, "subdivisions": 5 }, "ior": 1.6 ABBE},
    "environment": { "type": "sky" },
    "opaque": [ { "type": "painting", "center": [0, 0, -3.5], "size": [8, 6],
                  "texture": { "type": "checker", "squares": [16, 12], "resolution": [256, 192] } } ] })";
  const auto run = [&](const std::string& name, const std::string& abbe) {
    std::string text = ball;
    text.replace(text.find("ABBE"), 4, abbe);
    LabOptions o = labtest::labRunOptions("sphere_painting", 96);
    o.scenePath = dir.write(name, text);
    o.techniques = {"plane-normal-2"};
    return snell::lab::runLab(o);
  };
  const LabResult dispersive = run("dispersive.json", R"(, "abbe": 20)");
  const LabResult plain = run("plain.json", "");
  ASSERT_EQ(dispersive.rows.size(), 2u);
  ASSERT_EQ(plain.rows.size(), 2u);
  snell::lab::Scene s = snell::lab::loadScene(dir.file("dispersive.json"));
  s.camera.width = s.camera.height = 96;
  const snell::lab::SceneFrame frame = snell::lab::buildFrame(s);
  snell::lab::TraceOptions two;
  two.mode = snell::lab::TraceMode::TwoInterfaces;
  two.progress = false;
  const snell::lab::ReferenceTracer tracer(frame);
  const snell::lab::TraceResult each = tracer.render(frame.camera, two);
  two.channel = 1;
  const snell::lab::TraceResult green = tracer.render(frame.camera, two);
  const double dispersion = snell::lab::compareImages(each.color, green.color, each.mask).mse;
  for (std::size_t i = 0; i < 2; ++i) {
    const TechniqueRow& t = dispersive.rows[i];
    SCOPED_TRACE(t.name);
    std::printf("[lab] %s: %.4g vs the two-interface model (%.4g without dispersion; dispersion's own effect %.4g)\n",
                t.name.c_str(), t.mseTwo, plain.rows[i].mseTwo, dispersion);
    EXPECT_LT(t.mseTwo, plain.rows[i].mseTwo + 0.25 * dispersion);
    EXPECT_LE(t.cpuGpuBeyond1, 0.001);  // the GL rows and the C++ build read the same per-channel IORs
  }
}

// Rough glass: the truth samples its microfacets and says how noisy it is; the rows blur their colour reads
// through the mip chains, which the GPU builds (the colour pyramid pass) and the C++ side reads back, so both sides
// still agree pixel for pixel (a C++ side without those levels would read level 0 and differ wherever the
// chain blurs). A smooth ball's table has no truth noise at all.
TEST(LabRun, ARoughObjectIsBlurredAlikeOnBothSidesAndItsTruthsNoiseReported) {
  labtest::TempDir dir;
  const std::string ball = R"({
    "camera": { "position": [0, 0, 5], "fov": 40 },
    "object": { "mesh": { "type": "icosphere", "radius": 1, "subdivisions": 5 }, "ior": 1.5 ROUGH},
    "environment": { "type": "sky" },
    "opaque": [ { "type": "painting", "center": [0, 0, -3.5], "size": [8, 6],
                  "texture": { "type": "checker", "squares": [16, 12], "resolution": [256, 192] } } ] })";
  const auto run = [&](const std::string& name, const std::string& rough) {
    std::string text = ball;
    text.replace(text.find("ROUGH"), 5, rough);
    LabOptions o = labtest::labRunOptions("sphere_painting", 96);
    o.scenePath = dir.write(name, text);
    o.techniques = {"plane-normal-2"};
    o.truthSamples = 64;
    return snell::lab::runLab(o);
  };
  const LabResult rough = run("rough.json", R"(, "roughness": 0.4)");
  const LabResult smooth = run("smooth.json", "");
  EXPECT_EQ(rough.truthSamples, 64);
  EXPECT_GT(rough.truthNoise, 0.0);
  EXPECT_EQ(smooth.truthSamples, 0);
  EXPECT_EQ(smooth.truthNoise, 0.0);
  for (const LabResult* r : {&rough, &smooth})
    for (const TechniqueRow& t : r->rows) {
      SCOPED_TRACE(t.name);
      EXPECT_LE(t.cpuGpuBeyond1, 0.001);
      EXPECT_EQ(t.cpuGpuBeyond4Pixels, t.cpuGpuBeyond4Ties);
    }
  std::printf("[lab] rough ball: plane-normal-2 %.4g vs its truth (noise %.3g); smooth ball %.4g\n",
              rough.rows.front().mseFull, rough.truthNoise, smooth.rows.front().mseFull);
}

// The engine rows on a rough ball read through their engines' blurs (engine_rough.glsl) alike in GL and in the
// C++ mirror, Bevy's spiral included; three.js's bicubic and Bevy's taps read 8 texels where the smooth ball's
// rows read one, and Bevy's row reads three.js's point differently.
TEST(LabRun, EngineRowsOnARoughObjectBlurAlikeOnBothSides) {
  labtest::TempDir dir;
  const std::string ball = R"({
    "camera": { "position": [0, 0, 5], "fov": 40 },
    "object": { "mesh": { "type": "icosphere", "radius": 1, "subdivisions": 5 }, "ior": 1.5 ROUGH},
    "environment": { "type": "sky" },
    "opaque": [ { "type": "painting", "center": [0, 0, -3.5], "size": [8, 6],
                  "texture": { "type": "checker", "squares": [16, 12], "resolution": [256, 192] } } ] })";
  const auto run = [&](const std::string& name, const std::string& rough) {
    std::string text = ball;
    text.replace(text.find("ROUGH"), 5, rough);
    LabOptions o = labtest::labRunOptions("sphere_painting", 96);
    o.scenePath = dir.write(name, text);
    o.techniques = {"engine-threejs", "engine-bevy", "engine-filament-solid", "engine-hdrp-sphere", "engine-godot"};
    o.truthSamples = 16;
    return snell::lab::runLab(o);
  };
  const LabResult rough = run("rough.json", R"(, "roughness": 0.4)");
  const LabResult smooth = run("smooth.json", "");
  const auto row = [](const LabResult& r, const std::string& name) -> const TechniqueRow& {
    for (const TechniqueRow& t : r.rows)
      if (t.name == name) return t;
    throw std::runtime_error("no row " + name);
  };
  for (const LabResult* r : {&rough, &smooth})
    for (const TechniqueRow& t : r->rows) {
      if (t.engine == nullptr) continue;  // the image-space bound comes along; its agreement is tested above
      SCOPED_TRACE(t.name);
      EXPECT_LE(t.cpuGpuBeyond1, 0.001);
      EXPECT_EQ(t.cpuGpuBeyond4Pixels, t.cpuGpuBeyond4Ties);
      EXPECT_EQ(t.fetchMismatch, 0.0);
    }
  for (const std::string name : {"engine-threejs", "engine-bevy"}) {
    SCOPED_TRACE(name);
    EXPECT_GT(row(rough, name).fetchesPerPixel, row(smooth, name).fetchesPerPixel + 5.0);
  }
  EXPECT_NE(row(rough, "engine-bevy").mseFull, row(rough, "engine-threejs").mseFull);
  for (const TechniqueRow& t : rough.rows)
    std::printf("[lab] rough ball: %s %.4g (fetches %.1f); smooth ball %.4g (fetches %.1f)\n", t.name.c_str(),
                t.mseFull, t.fetchesPerPixel, row(smooth, t.name).mseFull, row(smooth, t.name).fetchesPerPixel);
}

// A glass ball under the sky alone: every exit ray rightly finds no scene and shows the environment, which
// is not a fallback to count (it was 100 % invalid); the exact paths that the rule trusts are the ray
// tracer's: before a painting that fills every exit ray's view none escapes.
TEST(LabRun, AFallbackToTheEnvironmentWhereTheExactPathEscapesIsNotInvalid) {
  labtest::TempDir dir;
  LabOptions o = labtest::labRunOptions("sphere_painting", 64);
  o.scenePath = dir.write("sky_ball.json", R"({ "camera": { "position": [0, 0, 5], "fov": 40 },
    "object": { "mesh": { "type": "icosphere", "radius": 1, "subdivisions": 4 } }, "environment": { "type": "sky" } })");
  o.techniques = {"plane-normal-2", "engine-threejs"};
  const LabResult r = snell::lab::runLab(o);
  ASSERT_EQ(r.rows.size(), 3u);
  for (const TechniqueRow& t : r.rows) {
    SCOPED_TRACE(t.name);
    EXPECT_EQ(t.invalidShare, 0.0);
    if (t.engine == nullptr) {
      EXPECT_GT(t.exitMissShare, 0.99);  // the exit rays did find nothing
    }
  }
  const std::string wall = dir.write("wall_ball.json", R"({ "camera": { "position": [0, 0, 5], "fov": 40 },
    "object": { "mesh": { "type": "icosphere", "radius": 1, "subdivisions": 4 } }, "environment": { "type": "sky" },
    "opaque": [ { "type": "painting", "center": [0, 0, -3.5], "size": [60, 60], "texture": { "type": "pattern" } } ] })");
  for (const std::string& scene : {dir.file("sky_ball.json"), wall}) {
    snell::lab::Scene s = snell::lab::loadScene(scene);
    s.camera.width = s.camera.height = 64;
    const snell::lab::SceneFrame frame = snell::lab::buildFrame(s);
    LabOptions quiet = o;
    snell::lab::LabResult result;
    const snell::lab::References refs = snell::lab::traceReferences(frame, {}, quiet, result);
    const std::size_t escapes = refs.escapes.count(), object = refs.full.mask.count();
    if (scene == dir.file("sky_ball.json")) {
      EXPECT_GT(escapes, object * 99 / 100) << "the ball's exact paths under the sky";
    } else {
      EXPECT_EQ(escapes, 0u) << "the painting fills the view behind the ball";
    }
  }
}

// The near plane cuts the whole front of the sphere: the ray tracer still sees the object (its rays start
// on the near plane, inside the sphere), the front-face pass shades nothing. That is an error naming the
// cause, not a table of equal MSEs with 0 fetches.
TEST(LabRun, ATechniqueThatShadedNothingIsAnError) {
  labtest::TempDir dir;
  const std::string scene = dir.file("cut.json");
  std::ofstream(scene) << R"({"camera": {"position": [0, 0, 5], "target": [0, 0, 0], "fov": 40, "near": 5.5,
    "resolution": [64, 64]}, "object": {"mesh": {"type": "icosphere", "radius": 1.0, "subdivisions": 3}}})";
  LabOptions o = options64("");
  o.scenePath = scene;
  o.techniques = {"single"};
  try {
    snell::lab::runLab(o);
    FAIL() << "no error";
  } catch (const snell::lab::Error& e) {
    EXPECT_EQ(e.kind(), snell::lab::ErrorKind::Render);
    EXPECT_NE(std::string(e.what()).find("technique single shaded none of the"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("near plane"), std::string::npos) << e.what();
  }
}

TEST(LabRun, AnObjectOutOfViewIsAnError) {
  labtest::TempDir dir;
  const std::string scene = dir.file("away.json");
  std::ofstream(scene) << R"({"camera": {"position": [0, 0, 5], "target": [0, 0, 10], "resolution": [64, 64]},
    "object": {"mesh": {"type": "icosphere", "radius": 1.0, "subdivisions": 3}}})";
  LabOptions o = options64("");
  o.scenePath = scene;
  try {
    snell::lab::runLab(o);
    FAIL() << "no error";
  } catch (const snell::lab::Error& e) {
    EXPECT_NE(std::string(e.what()).find("sees no pixel of the refractive object"), std::string::npos) << e.what();
  }
}

// The guard band on the sphere at the screen edge: the buffers then hold more of the exact paths (the
// bound's information error shrinks) and the image-space bound gets closer to the reference.
TEST(LabRun, GuardBandRecoversExitsOffTheViewport) {
  LabOptions o = options64("");
  o.scenePath = labtest::scenesDir() + "/sphere_edge.json";
  o.techniques = {"single"};
  o.frames = 1;
  o.guardBand = 0.0;
  const LabResult none = snell::lab::runLab(o);
  o.guardBand = 0.2;
  const LabResult band = snell::lab::runLab(o);
  EXPECT_EQ(none.guardBand, 0);
  EXPECT_EQ(band.guardBand, 16);  // 0.2 x 64 = 13 per side, grown to a 96-texel buffer (a multiple of 32)
  std::printf("[guard band] information share %.3f -> %.3f, MSE %.4g -> %.4g; bound %.4g -> %.4g\n",
              none.boundInformationShare, band.boundInformationShare, none.boundInformationMse,
              band.boundInformationMse, none.row("image-space-bound")->mseTwo, band.row("image-space-bound")->mseTwo);
  EXPECT_GT(none.boundInformationShare, 0.05);  // the scene's point: many exits leave the viewport
  EXPECT_LT(band.boundInformationShare, 0.6 * none.boundInformationShare);
  EXPECT_LT(band.row("image-space-bound")->mseTwo, 0.8 * none.row("image-space-bound")->mseTwo);
  for (const LabResult* r : {&none, &band})
    for (const TechniqueRow& t : r->rows) EXPECT_EQ(t.cpuGpuBeyond4Pixels, t.cpuGpuBeyond4Ties) << t.name;
}

// The environment basis handed to the shaders reproduces the lab's
// equirectangular mapping, rotation included, through snellEquirectUv.
TEST(LabRun, EnvironmentBasisMatchesTheLabMapping) {
  snell::lab::SceneFrame f;
  f.camera.position = snell::vec3(1.0f, 0.5f, 4.0f);
  f.objects.push_back({snell::lab::makeIcosphere(1.0f, 1), 1.5f, snell::vec3(0.0f)});
  f.environment = snell::lab::Environment(snell::Image(8, 4), 30.0f);
  const snell::lab::ShadeConstants k = snell::lab::shadeConstants(f, 0);
  const snell::mat3 worldFromView = snell::mat3(f.camera.worldFromView());
  for (const snell::vec3 v : {snell::vec3(0.1f, 0.2f, -1.0f), snell::vec3(-0.7f, -0.3f, -0.5f), snell::vec3(0.4f, 0.9f, 0.2f)}) {
    const snell::vec2 want = snell::lab::directionToEquirectUv(worldFromView * v, 30.0f);
    const snell::vec2 got = snell::snellEquirectUv(v.x * k.params.envX + v.y * k.params.envY + v.z * k.params.envZ);
    const float du = std::abs(want.x - got.x);
    EXPECT_LT(std::min(du, 1.0f - du), 1e-4f);
    EXPECT_NEAR(want.y, got.y, 1e-4f);
  }
}

// The executable: exit code and stderr.
struct ExeRun {
  int code = -1;
  std::string err;
};
ExeRun runLabExe(const std::string& args, const labtest::TempDir& dir) {
  const std::string errFile = dir.file("stderr.txt");
  const std::string cmd = std::string("'") + SNELL_LAB_EXE + "' " + args + " >/dev/null 2>'" + errFile + "'";
  const int status = std::system(cmd.c_str());
  ExeRun r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(errFile);
  std::stringstream s;
  s << in.rdbuf();
  r.err = s.str();
  return r;
}

TEST(LabCli, MissingSceneFileIsExitCode3WithThePath) {
  labtest::TempDir dir;
  const std::string missing = dir.file("no_such_scene.json");
  const ExeRun r = runLabExe("'" + missing + "' -q --out '" + dir.file("o") + "'", dir);
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_NE(r.err.find(missing), std::string::npos) << r.err;
}

TEST(LabCli, MalformedJsonIsExitCode4) {
  labtest::TempDir dir;
  const std::string bad = dir.write("bad.json", "{ \"camera\": { \"position\": [0, 0, 5] ,, }\n");
  const ExeRun r = runLabExe("'" + bad + "' -q --out '" + dir.file("o") + "'", dir);
  EXPECT_EQ(r.code, 4) << r.err;
  EXPECT_NE(r.err.find("bad.json"), std::string::npos) << r.err;
}

TEST(LabCli, SchemaErrorIsExitCode4NamingTheField) {
  labtest::TempDir dir;
  const std::string bad = dir.write("fov.json", R"({
  "camera": { "position": [0, 0, 5], "fov": "wide" },
  "object": { "mesh": { "type": "icosphere" } }
})");
  const ExeRun r = runLabExe("'" + bad + "' -q --out '" + dir.file("o") + "'", dir);
  EXPECT_EQ(r.code, 4) << r.err;
  EXPECT_NE(r.err.find("camera.fov"), std::string::npos) << r.err;
}

TEST(LabCli, UsageErrorsAreExitCode2) {
  labtest::TempDir dir;
  EXPECT_EQ(runLabExe("--technique no-such-technique -q", dir).code, 2);
  EXPECT_EQ(runLabExe("--size 64by64 -q", dir).code, 2);
  EXPECT_EQ(runLabExe("--backend vulkan -q", dir).code, 2);
  EXPECT_EQ(runLabExe("--frames 0 -q", dir).code, 2);
  const ExeRun help = runLabExe("--help", dir);
  EXPECT_EQ(help.code, 0);
}

// The messages a user meets first read clearly.
TEST(LabCli, UsageMessagesSayWhatIsWrongAndWhatWouldBeRight) {
  labtest::TempDir dir;
  const ExeRun typo = runLabExe("--techniqe single -q", dir);
  EXPECT_EQ(typo.code, 2);
  EXPECT_NE(typo.err.find("snell-lab: unknown option '--techniqe'; did you mean '--technique'?"), std::string::npos)
      << typo.err;
  const ExeRun far = runLabExe("--frobnicate -q", dir);
  EXPECT_EQ(far.code, 2);
  EXPECT_EQ(far.err.find("did you mean"), std::string::npos) << far.err;  // no guess for a word that is not close
  const ExeRun small = runLabExe("--size 4x4 -q", dir);
  EXPECT_EQ(small.code, 2);
  EXPECT_NE(small.err.find("--size: expected WxH with 8 <= W, H <= 8192 (e.g. 512x512), got '4x4'"), std::string::npos)
      << small.err;
  const ExeRun technique = runLabExe("--technique plane-normal -q", dir);
  EXPECT_EQ(technique.code, 2);
  EXPECT_NE(technique.err.find("unknown technique 'plane-normal'; valid: single, plane-normal-0"), std::string::npos)
      << technique.err;
  const std::string tiny = dir.write("tiny.json", R"({"camera": {"position": [0, 0, 5], "resolution": [4, 4]},
    "object": {"mesh": {"type": "icosphere"}}})");
  const ExeRun scene = runLabExe("'" + tiny + "' -q --out '" + dir.file("o") + "'", dir);
  EXPECT_EQ(scene.code, 4) << scene.err;
  EXPECT_NE(scene.err.find("camera.resolution"), std::string::npos) << scene.err;
  EXPECT_NE(scene.err.find("[8, 8192]"), std::string::npos) << scene.err;
  // CLI11's own messages carry the program's name too, as every other error does.
  const ExeRun backend = runLabExe("--backend vulkan -q", dir);
  EXPECT_EQ(backend.code, 2);
  EXPECT_EQ(backend.err.rfind("snell-lab: --backend: vulkan not in {auto,osmesa,egl}", 0), 0u) << backend.err;
  // An empty name in the list is a typo, not a shorter list.
  const ExeRun empty = runLabExe("-t 'single,,' -q", dir);
  EXPECT_EQ(empty.code, 2);
  EXPECT_NE(empty.err.find("snell-lab: --technique 'single,,': an empty name in the list"), std::string::npos)
      << empty.err;
}

// A window modelled as one quad: the lab renders it (every ray through it falls back) and says why.
TEST(LabCli, AnOpenMeshIsAWarningNamingIt) {
  labtest::TempDir dir;
  dir.write("window.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n");
  const std::string scene = dir.write("window.json", R"({ "camera": { "position": [0, 0, 5] },
    "object": { "mesh": { "type": "obj", "path": "window.obj" } } })");
  const ExeRun run = runLabExe("'" + scene + "' --size 32x32 -t single -q --out ''", dir);
  EXPECT_EQ(run.code, 0) << run.err;
  EXPECT_NE(run.err.find("snell-lab: warning: object (" + dir.file("window.obj") +
                         "): the mesh is open (4 edges with one triangle)"),
            std::string::npos)
      << run.err;
  const ExeRun ball = runLabExe("'" + labtest::scenesDir() + "/sphere_painting.json' --size 32x32 -t single -q --out ''", dir);
  EXPECT_EQ(ball.err.find("open"), std::string::npos) << ball.err;
}

// A frame larger than the memory budget is refused at once with the estimate and a size that fits, before
// the ray trace or a buffer (8192x8192: about 140 GB with every row).
TEST(LabCli, AFrameOverTheMemoryBudgetIsRefusedWithTheEstimate) {
  labtest::TempDir dir;
  const auto start = std::chrono::steady_clock::now();
  const ExeRun big = runLabExe("--size 8192x8192 -q --out ''", dir);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 20.0);
  EXPECT_EQ(big.code, 2) << big.err;
  EXPECT_NE(big.err.find("snell-lab: 8192x8192 with 1 object and "), std::string::npos) << big.err;
  EXPECT_NE(big.err.find("of memory, over the lab's budget of"), std::string::npos) << big.err;
  EXPECT_NE(big.err.find("choose a smaller --size ("), std::string::npos) << big.err;
}

}  // namespace
