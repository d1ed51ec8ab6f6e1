//! The browser binding (wasm32 only): one raw binding per core type — the physics
//! [`Session`](session::WebSession) and the [`Classroom`](classroom::WebClassroom) around it, which
//! the page's typed façade (`www/js/flexarm.js`) composes — and the wgpu
//! [`Renderer`](renderer::Renderer) that draws the session. This layer converts and
//! forwards — Rust values to JS objects, core errors to JS `Error`s — and decides nothing.
//!
//! A Rust panic is reported to the page through `window.flexarmPanic(message)` if the page
//! defines it.

pub mod classroom;
mod data;
mod figure;
mod gpu;
pub mod offline;
pub mod renderer;
mod sensors;
pub mod session;

use serde::Serialize;
use wasm_bindgen::prelude::*;

pub use classroom::WebClassroom;
pub use renderer::Renderer;
pub use session::{arms, lesson_source_path, presets, schema, spectral_radius, WebSession};

#[wasm_bindgen(start)]
fn start() {
    std::panic::set_hook(Box::new(|info| {
        let message = format!("flexarm crashed: {info}");
        web_sys::console::error_1(&message.clone().into());
        if let Some(window) = web_sys::window() {
            if let Ok(f) = js_sys::Reflect::get(&window, &"flexarmPanic".into()) {
                if let Some(f) = f.dyn_ref::<js_sys::Function>() {
                    let _ = f.call1(&JsValue::NULL, &message.into());
                }
            }
        }
    }));
}

/// A Rust value as a plain JS object (maps become objects, not `Map`s).
pub(crate) fn to_js<T: Serialize + ?Sized>(value: &T) -> Result<JsValue, JsError> {
    value
        .serialize(&serde_wasm_bindgen::Serializer::json_compatible())
        .map_err(|e| JsError::new(&format!("could not convert the result for JavaScript: {e}")))
}

/// A core error as a JS `Error` with its message.
pub(crate) fn js_error(e: impl core::fmt::Display) -> JsError {
    JsError::new(&e.to_string())
}

/// Milliseconds from the page's clock (0 where there is none).
pub(crate) fn now_ms() -> f64 {
    web_sys::window().and_then(|w| w.performance()).map_or(0.0, |p| p.now())
}
