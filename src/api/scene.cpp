// Scene (include/tmcert/scene.h): the validated internal scene, shared.
#include "src/scene/parse.h"

#include "src/api/internal.h"

#include <stdexcept>

namespace tmcert::api {

namespace {

Scene wrap(tmcert::Scene&& scene) {
  return Scene(std::make_shared<const Scene::Impl>(
      Scene::Impl{std::make_shared<const tmcert::Scene>(std::move(scene))}));
}

}  // namespace

Scene::Scene(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}

Scene Scene::from_file(const std::string& path) {
  return public_errors([&] { return wrap(tmcert::parse_scene_file(path)); });
}

Scene Scene::from_json(const std::string& text, const std::string& source) {
  return public_errors([&] { return wrap(tmcert::parse_scene_text(text, source)); });
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

}  // namespace tmcert::api
