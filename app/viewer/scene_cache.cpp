#include "scene_cache.h"

namespace holefill::viewer {

SceneCache::~SceneCache() { release(); }

void SceneCache::release() {
  if (framebuffer_) glDeleteFramebuffers(1, &framebuffer_);
  if (color_) glDeleteRenderbuffers(1, &color_);
  if (depth_) glDeleteRenderbuffers(1, &depth_);
  framebuffer_ = color_ = depth_ = 0;
  width_ = height_ = 0;
}

bool SceneCache::make(int width, int height) {
  if (framebuffer_ && width == width_ && height == height_) return true;
  release();
  glGenFramebuffers(1, &framebuffer_);
  glGenRenderbuffers(1, &color_);
  glGenRenderbuffers(1, &depth_);
  glBindRenderbuffer(GL_RENDERBUFFER, color_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depth_);
  const bool complete = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (!complete) {
    release();
    return false;
  }
  width_ = width;
  height_ = height;
  return true;
}

void SceneCache::copy_to_window() const {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

bool SceneCache::show(const SceneKey& key) {
  if (!framebuffer_ || !key_ || !(*key_ == key)) return false;
  copy_to_window();
  return true;
}

void SceneCache::begin(const SceneKey& key) {
  key_.reset();
  drawing_ = make(key.framebuffer[0], key.framebuffer[1]);
  if (!drawing_) return;  // no offscreen framebuffer: draw straight into the window's
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  key_ = key;
}

void SceneCache::end() {
  if (!drawing_) return;
  drawing_ = false;
  copy_to_window();
}

}  // namespace holefill::viewer
