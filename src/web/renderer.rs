//! The wgpu renderer (placeholder until the renderer lands).
