#pragma once
// Headless RGB-D rendering of a SceneSnapshot through MRPT's off-screen renderer (EGL): the colour
// image the blob detector measures on, and metric z-depth consistent with CameraModel.

#include <opencv2/core/mat.hpp>

#include <memory>

#include "opf/sim/body.h"
#include "opf/sim/camera_model.h"

namespace opf::sim {

struct SceneRendererOptions {
  /// Clip range, metres of z-depth. Geometry nearer than `near_clip_m` or beyond `far_clip_m` is
  /// not drawn at all. 0.1-3 m holds both paper cameras' scenes (0.2-0.9 m deep).
  double near_clip_m = 0.1;
  double far_clip_m = 3.0;
  /// Lighting: one directional light along the camera's optical axis, so a surface facing the
  /// camera shows exactly its Colour (ambient + diffuse = 1) and a surface seen edge-on shows
  /// `ambient` times it. Hue and saturation are unchanged by the shading, only the HSV value.
  double ambient = 0.6;
  double diffuse = 0.4;
  /// Where no body is hit; unsaturated so that no colour detector fires on it.
  Colour background{40, 40, 40};
  /// Tessellation: a sphere is drawn as an inscribed polyhedron with this many divisions in
  /// longitude and latitude, a cylinder as an inscribed prism with this many sides; the drawn
  /// silhouette is (n / 2 pi) sin(2 pi / n) of the true one: -0.3% at 48, -0.16% at 64.
  int sphere_divisions = 48;
  int cylinder_slices = 64;
  /// MRPT 2.5's shaders declare every position `mediump`, which Mesa's software renderer
  /// evaluates at half precision: depth is then off by 0.1-0.4% of the distance (1-3 mm at
  /// 0.8 m) and worse far from the world origin. With this on, the lit-triangle shader (the one
  /// spheres, cylinders and boxes use) is replaced by the same program in `highp`, which brings
  /// the error down to <0.01% (0.08 mm over 0.2-1.1 m: the quantisation of MRPT's depth look-up
  /// table). The replacement copies MRPT 2.5.8's shader and its uniforms; with another MRPT
  /// version, check it against that version's triangles-light shader (a mismatch throws on the
  /// first render) and re-run the depth tests.
  bool high_precision_shaders = true;
};

/// One rendered frame: `bgr` is CV_8UC3 (OpenCV's BGR order), `depth` CV_32FC1 z-depth in metres
/// with 0 where nothing was hit (as depth sensors report "no return"), both height x width of the
/// camera, row 0 at the top.
struct RgbdFrame {
  cv::Mat bgr;
  cv::Mat depth;
};

/// Draws each body as a coloured sphere, cylinder or box at its BodyPose and reads back colour
/// and depth. The OpenGL context and the scene are kept between frames: a new frame only updates
/// the poses (5-7 ms at 640x480 on two cores, mostly Mesa's rasteriser threads), and rebuilds the
/// objects only when the list of bodies changes shape, size or colour. Creating the context costs
/// ~0.15 s the first time in a process (Mesa start-up), ~20 ms after; the first frame ~30 ms more
/// (shader compilation).
///
/// Constraints inherited from MRPT 2.5.8 (measured): only ONE renderer may be alive in a process
/// at a time, because destroying an MRPT off-screen renderer terminates the EGL display every
/// other one uses (the next render then fails); constructing a second one while another is alive
/// throws std::logic_error instead of crashing later. A renderer renders only from the thread that
/// created it (its context is current, and MRPT keeps its shaders, only there); render() throws
/// std::logic_error from another thread.
class SceneRenderer {
 public:
  /// Creates the headless EGL context. Throws std::runtime_error (with MRPT's message) when no
  /// EGL display or context can be created, std::invalid_argument for bad options and
  /// std::logic_error if another SceneRenderer is alive.
  explicit SceneRenderer(const CameraModel& camera, const SceneRendererOptions& options = {});
  ~SceneRenderer();
  SceneRenderer(const SceneRenderer&) = delete;
  SceneRenderer& operator=(const SceneRenderer&) = delete;
  SceneRenderer(SceneRenderer&&) noexcept;
  SceneRenderer& operator=(SceneRenderer&&) noexcept;

  /// Takes effect from the next frame; the image size must stay that of the constructor's camera
  /// (the off-screen buffer has a fixed size): throws std::invalid_argument otherwise.
  void set_camera(const CameraModel& camera);
  const CameraModel& camera() const;
  const SceneRendererOptions& options() const;

  /// Renders into `frame`, reusing its buffers when they already have the right size and type.
  void render(const SceneSnapshot& scene, RgbdFrame& frame);
  RgbdFrame render(const SceneSnapshot& scene);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace opf::sim
