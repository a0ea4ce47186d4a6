#include "opf/sim/scene_renderer.h"

#include <mrpt/img/CImage.h>
#include <mrpt/img/TCamera.h>
#include <mrpt/math/CMatrixDynamic.h>
#include <mrpt/opengl/CBox.h>
#include <mrpt/opengl/CCamera.h>
#include <mrpt/opengl/CCylinder.h>
#include <mrpt/opengl/CFBORender.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CSphere.h>
#include <mrpt/opengl/DefaultShaders.h>
#include <mrpt/opengl/Shader.h>
#include <mrpt/opengl/opengl_api.h>
#include <mrpt/poses/CPose3D.h>

#include <atomic>
#include <cstring>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "opf/core/pose_conversion.h"

namespace opf::sim {
namespace {

// MRPT 2.5.8's lit-triangle program (DefaultShaderID::TRIANGLES_LIGHT) with every `mediump`
// turned into `highp`; the uniforms and attributes are the ones MRPT's render loop sets.
constexpr const char* kHighpTrianglesVertexShader = R"(#version 300 es
precision highp float;
in vec3 position;
in vec4 vertexColor;
in vec3 vertexNormal;
uniform highp mat4 p_matrix;
uniform highp mat4 v_matrix;
uniform highp mat4 m_matrix;
out highp vec3 frag_position, frag_normal;
out highp vec4 frag_materialColor;
void main()
{
    frag_position = vec3(m_matrix * vec4(position, 1.0));
    frag_normal   = normalize(mat3(transpose(inverse(m_matrix))) * vertexNormal);
    frag_materialColor = vertexColor;
    gl_Position = p_matrix * v_matrix * vec4(frag_position, 1.0);
}
)";

constexpr const char* kHighpTrianglesFragmentShader = R"(#version 300 es
precision highp float;
uniform highp vec4 light_diffuse, light_ambient;
uniform highp vec3 light_direction;
in highp vec3 frag_position, frag_normal;
in highp vec4 frag_materialColor;
out highp vec4 color;
void main()
{
    highp float diff = max(dot(normalize(frag_normal), -light_direction), 0.0);
    highp vec4 diffuse_factor = diff * light_diffuse;
    color = frag_materialColor * (diffuse_factor + light_ambient);
}
)";

// Enforces "one live MRPT off-screen renderer per process" (see the class comment): the only
// process-wide state here, and it exists to turn a later GL crash into an immediate, explained
// error.
std::atomic<bool>& renderer_alive() {
  static std::atomic<bool> alive{false};
  return alive;
}

class SingleRendererGuard {
 public:
  SingleRendererGuard() {
    if (renderer_alive().exchange(true)) {
      throw std::logic_error(
          "SceneRenderer: another SceneRenderer is alive; MRPT 2.5's off-screen renderer supports "
          "only one live instance per process (destroying one terminates the shared EGL display)");
    }
  }
  ~SingleRendererGuard() { renderer_alive().store(false); }
  SingleRendererGuard(const SingleRendererGuard&) = delete;
  SingleRendererGuard& operator=(const SingleRendererGuard&) = delete;
};

void validate(const SceneRendererOptions& o) {
  if (!(o.near_clip_m > 0.0 && o.far_clip_m > o.near_clip_m)) {
    throw std::invalid_argument("SceneRendererOptions: need 0 < near_clip_m < far_clip_m");
  }
  if (!(o.ambient >= 0.0 && o.diffuse >= 0.0)) {
    throw std::invalid_argument("SceneRendererOptions: ambient and diffuse must be >= 0");
  }
  if (o.sphere_divisions < 3 || o.cylinder_slices < 3) {
    throw std::invalid_argument("SceneRendererOptions: need at least 3 divisions and slices");
  }
}

mrpt::opengl::CFBORender::Parameters fbo_parameters(const CameraModel& camera) {
  if (camera.width <= 0 || camera.height <= 0) {
    throw std::invalid_argument("SceneRenderer: the camera's image size must be positive");
  }
  return {static_cast<unsigned int>(camera.width), static_cast<unsigned int>(camera.height)};
}

bool same_appearance(const Body& a, const Body& b) {
  return a.shape == b.shape && a.size == b.size && a.colour.r == b.colour.r &&
         a.colour.g == b.colour.g && a.colour.b == b.colour.b;
}

mrpt::opengl::CRenderizable::Ptr make_object(const Body& body,
                                             const SceneRendererOptions& options) {
  mrpt::opengl::CRenderizable::Ptr object;
  switch (body.shape) {
    case Shape::kSphere:
      object = mrpt::opengl::CSphere::Create(static_cast<float>(body.size.x()),
                                             options.sphere_divisions, options.sphere_divisions);
      break;
    case Shape::kCylinder: {
      const auto radius = static_cast<float>(body.size.x());
      auto cylinder = mrpt::opengl::CCylinder::Create(
          radius, radius, static_cast<float>(body.size.z()), options.cylinder_slices);
      cylinder->setHasBases(true, true);
      object = cylinder;
      break;
    }
    case Shape::kBox: {
      const Eigen::Vector3d half = 0.5 * body.size;
      object = mrpt::opengl::CBox::Create(mrpt::math::TPoint3D(-half.x(), -half.y(), -half.z()),
                                          mrpt::math::TPoint3D(half.x(), half.y(), half.z()));
      break;
    }
  }
  if (!object) throw std::invalid_argument("SceneRenderer: unknown body shape");
  object->setColor_u8(body.colour.r, body.colour.g, body.colour.b);
  object->setName(body.name);
  return object;
}

}  // namespace

struct SceneRenderer::Impl {
  // Declared first so it is released last, after the EGL context is gone.
  SingleRendererGuard guard;
  CameraModel camera;
  SceneRendererOptions options;
  mrpt::opengl::CFBORender fbo;
  // Declared after `fbo` so the scene's GL objects are freed while the context still exists.
  mrpt::opengl::COpenGLScene::Ptr scene = mrpt::opengl::COpenGLScene::Create();
  std::vector<mrpt::opengl::CRenderizable::Ptr> objects;
  std::vector<Body> built_for;
  mrpt::img::CImage rgb;
  mrpt::math::CMatrixFloat depth;
  // The EGL context is current, and the viewport's shaders exist, only in this thread.
  std::thread::id owner = std::this_thread::get_id();

  Impl(const CameraModel& cam, const SceneRendererOptions& opts)
      : camera(cam), options(opts), fbo(create_fbo(cam)) {
    auto viewport = scene->getViewport();
    viewport->setViewportClipDistances(static_cast<float>(options.near_clip_m),
                                       static_cast<float>(options.far_clip_m));
    viewport->setCustomBackgroundColor(mrpt::img::TColorf(
        mrpt::img::TColor(options.background.r, options.background.g, options.background.b)));
    auto& light = viewport->lightParameters();
    const auto a = static_cast<float>(options.ambient);
    const auto d = static_cast<float>(options.diffuse);
    light.ambient = mrpt::img::TColorf(a, a, a, 1.0f);
    light.diffuse = mrpt::img::TColorf(d, d, d, 1.0f);
    if (options.high_precision_shaders) install_highp_shaders();
    apply_camera();
  }

  static mrpt::opengl::CFBORender create_fbo(const CameraModel& cam) {
    try {
      return mrpt::opengl::CFBORender(fbo_parameters(cam));
    } catch (const std::invalid_argument&) {
      throw;
    } catch (const std::exception& e) {
      std::string message = "SceneRenderer: cannot create MRPT's headless EGL renderer: ";
      message.append(e.what());
      throw std::runtime_error(message);
    }
  }

  void install_highp_shaders() {
    auto viewport = scene->getViewport();
    // Load MRPT's programs first: the viewport loads them only when it has none, and the points,
    // wireframe and text programs must stay available.
    viewport->loadDefaultShaders();
    std::vector<mrpt::opengl::Shader> shaders(2);
    std::string errors;
    if (!shaders[0].compile(GL_VERTEX_SHADER, kHighpTrianglesVertexShader, errors) ||
        !shaders[1].compile(GL_FRAGMENT_SHADER, kHighpTrianglesFragmentShader, errors)) {
      std::string message = "SceneRenderer: cannot compile the highp triangle shader: ";
      message.append(errors);
      throw std::runtime_error(message);
    }
    auto program = std::make_shared<mrpt::opengl::Program>();
    if (!program->linkProgram(shaders, errors)) {
      std::string message = "SceneRenderer: cannot link the highp triangle shader: ";
      message.append(errors);
      throw std::runtime_error(message);
    }
    for (const char* name : {"p_matrix", "v_matrix", "m_matrix", "light_diffuse", "light_ambient",
                             "light_direction"}) {
      program->declareUniform(name);
    }
    for (const char* name : {"position", "vertexColor", "vertexNormal"}) {
      program->declareAttribute(name);
    }
    viewport->shaders()[mrpt::opengl::DefaultShaderID::TRIANGLES_LIGHT] = program;
  }

  void apply_camera() {
    mrpt::opengl::CCamera view;
    // 6-DOF mode takes the pose as MRPT's camera convention, which is OpenCV's (x right, y down,
    // z forward), so world_from_camera goes in unchanged.
    view.set6DOFMode(true);
    view.setPose(opf::make_pose(camera.world_from_camera.translation(),
                                Eigen::Quaterniond(camera.world_from_camera.linear())));
    mrpt::img::TCamera intrinsics;
    intrinsics.ncols = static_cast<uint32_t>(camera.width);
    intrinsics.nrows = static_cast<uint32_t>(camera.height);
    intrinsics.fx(camera.fx);
    intrinsics.fy(camera.fy);
    // MRPT's pinhole projection puts pixel edges at integers (OpenGL window coordinates), ours
    // puts pixel centres there: measured, a point at our (cx, cy) lands in the pixel centre only
    // with MRPT's principal point half a pixel further.
    intrinsics.cx(camera.cx + 0.5);
    intrinsics.cy(camera.cy + 0.5);
    view.setProjectiveFromPinhole(intrinsics);
    fbo.setCamera(*scene, view);

    // MRPT lights in world coordinates (the shader compares world-frame normals).
    const Eigen::Vector3d f = camera.forward();
    scene->getViewport()->lightParameters().direction = mrpt::math::TVector3Df(
        static_cast<float>(f.x()), static_cast<float>(f.y()), static_cast<float>(f.z()));
  }

  void sync_objects(const SceneSnapshot& snapshot) {
    if (snapshot.poses.size() != snapshot.bodies.size()) {
      throw std::invalid_argument("SceneRenderer::render: the snapshot needs one pose per body");
    }
    bool rebuild = built_for.size() != snapshot.bodies.size();
    for (std::size_t i = 0; !rebuild && i < snapshot.bodies.size(); ++i) {
      rebuild = !same_appearance(built_for[i], snapshot.bodies[i]);
    }
    if (rebuild) {
      auto viewport = scene->getViewport();
      viewport->clear();
      objects.clear();
      for (const Body& body : snapshot.bodies) {
        objects.push_back(make_object(body, options));
        viewport->insert(objects.back());
      }
      built_for = snapshot.bodies;
    }
    for (std::size_t i = 0; i < objects.size(); ++i) {
      const BodyPose& pose = snapshot.poses[i];
      mrpt::poses::CPose3D world_from_body = opf::make_pose(pose.position, pose.orientation);
      if (snapshot.bodies[i].shape == Shape::kCylinder) {
        // MRPT's cylinder runs from its base (z = 0) to z = height; ours is centred.
        world_from_body =
            world_from_body +
            mrpt::poses::CPose3D(0.0, 0.0, -0.5 * snapshot.bodies[i].size.z(), 0.0, 0.0, 0.0);
      }
      objects[i]->setPose(world_from_body);
    }
  }

  void render(const SceneSnapshot& snapshot, RgbdFrame& frame) {
    if (std::this_thread::get_id() != owner) {
      throw std::logic_error("SceneRenderer::render: call it from the thread that created it");
    }
    sync_objects(snapshot);
    fbo.render_RGBD(*scene, rgb, depth);

    const int rows = camera.height;
    const int cols = camera.width;
    const cv::Mat bgr_view = rgb.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY);
    if (bgr_view.rows != rows || bgr_view.cols != cols || bgr_view.type() != CV_8UC3 ||
        rgb.getChannelsOrder() != std::string("BGR")) {
      throw std::runtime_error("SceneRenderer: unexpected image layout from MRPT");
    }
    bgr_view.copyTo(frame.bgr);

    if (depth.rows() != rows || depth.cols() != cols) {
      throw std::runtime_error("SceneRenderer: unexpected depth layout from MRPT");
    }
    frame.depth.create(rows, cols, CV_32FC1);
    // MRPT's dynamic matrices are row-major and unpadded, like a continuous cv::Mat.
    for (int r = 0; r < rows; ++r) {
      std::memcpy(frame.depth.ptr<float>(r), &depth(r, 0),
                  sizeof(float) * static_cast<std::size_t>(cols));
    }
  }
};

SceneRenderer::SceneRenderer(const CameraModel& camera, const SceneRendererOptions& options) {
  // Bad arguments are reported as such even while another renderer is alive.
  validate(options);
  fbo_parameters(camera);
  impl_ = std::make_unique<Impl>(camera, options);
}

SceneRenderer::~SceneRenderer() = default;
SceneRenderer::SceneRenderer(SceneRenderer&&) noexcept = default;
SceneRenderer& SceneRenderer::operator=(SceneRenderer&&) noexcept = default;

void SceneRenderer::set_camera(const CameraModel& camera) {
  if (camera.width != impl_->camera.width || camera.height != impl_->camera.height) {
    throw std::invalid_argument("SceneRenderer::set_camera: the image size cannot change");
  }
  impl_->camera = camera;
  impl_->apply_camera();
}

const CameraModel& SceneRenderer::camera() const {
  return impl_->camera;
}
const SceneRendererOptions& SceneRenderer::options() const {
  return impl_->options;
}

void SceneRenderer::render(const SceneSnapshot& scene, RgbdFrame& frame) {
  impl_->render(scene, frame);
}

RgbdFrame SceneRenderer::render(const SceneSnapshot& scene) {
  RgbdFrame frame;
  impl_->render(scene, frame);
  return frame;
}

}  // namespace opf::sim
