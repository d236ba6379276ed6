#include "impasto/render_gl/shader_program.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace impasto::render_gl {
namespace {

std::string shader_log(GLuint shader) {
  GLint length = 0;
  glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<size_t>(std::max(length, 1)), '\0');
  glGetShaderInfoLog(shader, length, nullptr, log.data());
  log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
  return log;
}

std::string program_log(GLuint program) {
  GLint length = 0;
  glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<size_t>(std::max(length, 1)), '\0');
  glGetProgramInfoLog(program, length, nullptr, log.data());
  log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
  return log;
}

GLuint compile(const ShaderSource& source) {
  const GLuint shader = glCreateShader(source.stage);
  if (shader == 0) throw std::runtime_error(source.name + ": glCreateShader failed");
  const char* text = source.text.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    std::string log = shader_log(shader);
    glDeleteShader(shader);
    throw std::runtime_error(source.name + ": GLSL compile error:\n" + log);
  }
  return shader;
}

}  // namespace

ShaderProgram::ShaderProgram(const std::vector<ShaderSource>& sources) {
  std::vector<GLuint> shaders;
  try {
    for (const ShaderSource& source : sources) shaders.push_back(compile(source));
  } catch (...) {
    for (GLuint shader : shaders) glDeleteShader(shader);
    throw;
  }
  id_ = glCreateProgram();
  for (GLuint shader : shaders) glAttachShader(id_, shader);
  glLinkProgram(id_);
  for (GLuint shader : shaders) {
    glDetachShader(id_, shader);
    glDeleteShader(shader);
  }
  GLint ok = GL_FALSE;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    std::string names;
    for (const ShaderSource& source : sources) names += (names.empty() ? "" : " + ") + source.name;
    std::string log = program_log(id_);
    glDeleteProgram(id_);
    id_ = 0;
    throw std::runtime_error(names + ": GLSL link error:\n" + log);
  }
}

ShaderProgram::~ShaderProgram() {
  if (id_ != 0) glDeleteProgram(id_);
}

ShaderProgram::ShaderProgram(ShaderProgram&& other) noexcept : id_(std::exchange(other.id_, 0)) {}

ShaderProgram& ShaderProgram::operator=(ShaderProgram&& other) noexcept {
  if (this != &other) {
    if (id_ != 0) glDeleteProgram(id_);
    id_ = std::exchange(other.id_, 0);
  }
  return *this;
}

GLint ShaderProgram::uniform(std::string_view name) const {
  return glGetUniformLocation(id_, std::string(name).c_str());
}

}  // namespace impasto::render_gl
