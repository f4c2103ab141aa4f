// Scene (include/tmcert/scene.h): the validated internal scene, shared.
#include "src/io/parse.h"

#include "src/api/internal.h"

#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace tmcert::api {

namespace {

Scene wrap(tmcert::Scene&& scene, std::vector<tmcert::SceneRobot>&& robots) {
  return Scene(std::make_shared<const Scene::Impl>(
      Scene::Impl{std::make_shared<const tmcert::Scene>(std::move(scene)), std::move(robots)}));
}

}  // namespace

Scene::Scene(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}

Scene Scene::from_file(const std::string& path) {
  return public_errors([&] {
    std::vector<tmcert::SceneRobot> robots;
    tmcert::Scene scene = tmcert::parse_scene_file(path, robots);
    return wrap(std::move(scene), std::move(robots));
  });
}

Scene Scene::from_file(const std::string& path, const std::vector<std::string>& package_paths) {
  return public_errors([&] {
    std::vector<tmcert::SceneRobot> robots;
    tmcert::Scene scene = tmcert::parse_scene_file(path, tmcert::ReadOptions{package_paths}, &robots);
    return wrap(std::move(scene), std::move(robots));
  });
}

Scene Scene::from_json(const std::string& text, const std::string& source) {
  return public_errors([&] {
    // As parse_scene_text(text, source): files relative to the directory
    // of `source` when it names a file, else to the current directory.
    std::error_code ec;
    std::string base;
    if (!source.empty() && std::filesystem::is_regular_file(source, ec))
      base = std::filesystem::path(source).parent_path().string();
    std::vector<tmcert::SceneRobot> robots;
    tmcert::Scene scene = tmcert::parse_scene_text(text, source, base, robots);
    return wrap(std::move(scene), std::move(robots));
  });
}

std::vector<std::string> Scene::body_names() const {
  std::vector<std::string> out;
  out.reserve(impl_->scene->bodies.size());
  for (const tmcert::Body& b : impl_->scene->bodies) out.push_back(b.name);
  return out;
}

std::size_t Scene::body_count() const { return impl_->scene->bodies.size(); }

bool Scene::moves(std::size_t body) const { return impl_->scene->bodies.at(body).moves(); }

std::vector<std::pair<std::string, std::string>> Scene::checks() const {
  const tmcert::Scene& s = *impl_->scene;
  std::vector<std::pair<std::string, std::string>> out;
  out.reserve(s.checks.size());
  for (const auto& [a, b] : s.checks) out.emplace_back(s.bodies[a].name, s.bodies[b].name);
  return out;
}

std::optional<Rational> Scene::epsilon() const {
  if (!impl_->scene->epsilon) return std::nullopt;
  return to_rational(*impl_->scene->epsilon);
}

Rational Scene::default_epsilon(const std::string& a, const std::string& b) const {
  const auto body = [&](const std::string& name) -> const tmcert::Body& {
    for (const tmcert::Body& x : impl_->scene->bodies)
      if (x.name == name) return x;
    throw std::out_of_range("Scene::default_epsilon: no body named \"" + name + "\"");
  };
  return to_rational(tmcert::default_epsilon(body(a), body(b)));
}

int Scene::max_depth() const { return impl_->scene->max_depth; }

const std::string& Scene::source() const { return impl_->scene->source; }
const std::vector<std::string>& Scene::notes() const { return impl_->scene->notes; }
const std::vector<std::string>& Scene::warnings() const { return impl_->scene->warnings; }

}  // namespace tmcert::api
