//! The wgpu renderer: uploads the triangles that [`crate::view::Scene`] tessellates and draws them
//! with one pipeline. WebGPU is used when the browser offers an adapter, WebGL2 otherwise.
//!
//! The GPU side is deliberately thin: one WGSL shader maps physical pixels to clip space (the
//! viewport size is a uniform) and passes the vertex colour through; alpha blending makes the
//! reference arm translucent. Two vertex buffers are reused and grow only when needed: the
//! static layer (the stability maps' cells and contours), uploaded only when the scene rebuilds it,
//! and the per-frame layer drawn over it. All geometry, layout and autoscaling lives in `view`,
//! where native tests cover it.

use std::sync::Arc;

use serde::Serialize;
use wasm_bindgen::prelude::*;
use web_sys::HtmlCanvasElement;

use super::{Simulation, StabilityMapJob};
use crate::view::{Color, MapSide, OptionsUpdate, PanelInfo, PoleInfo, Scene, SeriesInfo, Vertex, ViewOptions};

/// WGSL for both backends: pixel → clip space, colour passed through. When the surface only
/// offers an sRGB format the fragment shader decodes the (sRGB-encoded) colours to linear, so
/// the picture looks the same on every format.
const SHADER: &str = r#"
struct Viewport {
    // Canvas size in physical pixels.
    size: vec2<f32>,
    // 1.0 if the target encodes sRGB on write (colours must be decoded first), else 0.0.
    srgb_target: f32,
    _pad: f32,
};

@group(0) @binding(0) var<uniform> viewport: Viewport;

struct VertexOutput {
    @builtin(position) clip: vec4<f32>,
    @location(0) color: vec4<f32>,
};

@vertex
fn vs_main(@location(0) position: vec2<f32>, @location(1) color: vec4<f32>) -> VertexOutput {
    var out: VertexOutput;
    let ndc = vec2<f32>(
        position.x / viewport.size.x * 2.0 - 1.0,
        1.0 - position.y / viewport.size.y * 2.0,
    );
    out.clip = vec4<f32>(ndc, 0.0, 1.0);
    out.color = color;
    return out;
}

fn srgb_to_linear(c: vec3<f32>) -> vec3<f32> {
    let low = c / 12.92;
    let high = pow((c + vec3<f32>(0.055)) / 1.055, vec3<f32>(2.4));
    return select(high, low, c <= vec3<f32>(0.04045));
}

@fragment
fn fs_main(in: VertexOutput) -> @location(0) vec4<f32> {
    if (viewport.srgb_target > 0.5) {
        return vec4<f32>(srgb_to_linear(in.color.rgb), in.color.a);
    }
    return in.color;
}
"#;

/// Size of the uniform block: vec2 size, f32 flag, f32 padding.
const UNIFORM_BYTES: u64 = 16;
/// Smallest vertex buffer allocated, bytes.
const MIN_VERTEX_BUFFER: u64 = 256 * 1024;

/// Which browser graphics API draws.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Backend {
    WebGpu,
    WebGl2,
}

impl Backend {
    fn name(self) -> &'static str {
        match self {
            Backend::WebGpu => "WebGPU",
            Backend::WebGl2 => "WebGL2",
        }
    }
}

/// The device and surface of one backend.
struct Gpu {
    backend: Backend,
    surface: wgpu::Surface<'static>,
    adapter: wgpu::Adapter,
    device: wgpu::Device,
    queue: wgpu::Queue,
}

fn log(message: &str) {
    web_sys::console::log_1(&message.into());
}

fn warn(message: &str) {
    web_sys::console::warn_1(&message.into());
}

/// What `Renderer.layout()` returns.
#[derive(Serialize)]
struct LayoutReport {
    panels: Vec<PanelInfo>,
    /// "single" after `render`, "pair" after `renderPair`.
    mode: &'static str,
    /// How each shown run is drawn (legend): one entry, or two in pair mode.
    series: Vec<SeriesInfo>,
    /// Every marker of the pole plot, for hover readouts.
    poles: Vec<PoleInfo>,
    spring_magnification: f64,
    backend: &'static str,
}

/// Draws a [`Simulation`] on a canvas: the arm on one side, the error (and torque) traces on the
/// other, below them the pole plot and the stability maps without and with preliminary feedback.
/// Create it with `await Renderer.create(canvas)`, call `resize` when the canvas' CSS size or the
/// device-pixel ratio changes, `setMap("off"|"on", job)` when a [`StabilityMapJob`] has new rows,
/// and `render(sim)` (or `renderPair(a, b)` to compare two runs) once per animation frame.
#[wasm_bindgen]
pub struct Renderer {
    backend: Backend,
    canvas: HtmlCanvasElement,
    surface: wgpu::Surface<'static>,
    device: wgpu::Device,
    queue: wgpu::Queue,
    config: wgpu::SurfaceConfiguration,
    /// True if the surface format is sRGB (the shader then decodes colours).
    srgb_target: bool,
    pipeline: wgpu::RenderPipeline,
    uniforms: wgpu::Buffer,
    bind_group: wgpu::BindGroup,
    vertices: wgpu::Buffer,
    /// The static layer (stability maps), drawn before `vertices`.
    static_vertices: wgpu::Buffer,
    /// Vertices in `static_vertices`, and the scene's static generation they came from.
    static_count: u32,
    static_uploaded: Option<u64>,
    /// Set once a frame had more vertices than the device allows in one buffer.
    warned_truncation: bool,
    scene: Scene,
}

#[wasm_bindgen]
impl Renderer {
    /// A renderer on `canvas`: WebGPU when `navigator.gpu` yields an adapter, WebGL2 otherwise.
    /// The choice is logged to the console. Rejects with a readable message if neither works.
    pub async fn create(canvas: HtmlCanvasElement) -> Result<Renderer, JsError> {
        let mut failures: Vec<String> = Vec::new();
        let mut gpu = None;
        if wgpu::util::is_browser_webgpu_supported().await {
            match open_webgpu(&canvas).await {
                Ok(g) => gpu = Some(g),
                Err(e) => {
                    warn(&format!("flexarm: WebGPU is offered but could not be used ({e}); trying WebGL2"));
                    failures.push(format!("WebGPU: {e}"));
                }
            }
        } else {
            failures.push("WebGPU: navigator.gpu is missing or gives no adapter".into());
        }
        if gpu.is_none() {
            match open_webgl2(&canvas).await {
                Ok(g) => gpu = Some(g),
                Err(e) => failures.push(format!("WebGL2: {e}")),
            }
        }
        let Some(gpu) = gpu else {
            return Err(JsError::new(&format!(
                "flexarm cannot draw: neither WebGPU nor WebGL2 is available in this browser ({}). \
                 Try a current Chrome, Edge or Firefox with hardware acceleration enabled.",
                failures.join("; ")
            )));
        };
        let info = gpu.adapter.get_info();
        let device = if info.name.is_empty() { String::new() } else { format!(" on {}", info.name) };
        log(&format!("flexarm: drawing with {}{device}", gpu.backend.name()));
        Self::with_gpu(canvas, gpu)
    }

    /// "WebGPU" or "WebGL2".
    pub fn backend(&self) -> String {
        self.backend.name().to_string()
    }

    /// Sets the canvas' drawing-buffer size to `css_width × css_height × device_pixel_ratio`
    /// physical pixels and re-lays out the panels. Invalid numbers count as 1; a size beyond the
    /// device's texture limit lowers the effective pixel ratio instead of failing.
    pub fn resize(&mut self, css_width: f64, css_height: f64, device_pixel_ratio: f64) {
        let sane = |v: f64| if v.is_finite() && v >= 1.0 { v } else { 1.0 };
        let (w, h) = (sane(css_width), sane(css_height));
        let dpr = if device_pixel_ratio.is_finite() && device_pixel_ratio > 0.0 { device_pixel_ratio } else { 1.0 };
        let max = f64::from(self.device.limits().max_texture_dimension_2d.max(1));
        let dpr = dpr.min(max / w).min(max / h);
        self.scene.resize(w, h, dpr);
        self.apply_size();
    }

    /// Changes drawing options: `{show_torque?: bool, time_window?: seconds,
    /// spring_magnification?: number, show_poles?: bool, show_map?: bool}` (the pole plot and the
    /// stability maps are shown by default). Missing fields stay as they are; an invalid or
    /// unknown field changes nothing and throws.
    #[wasm_bindgen(js_name = setOptions)]
    pub fn set_options(&mut self, options: JsValue) -> Result<(), JsError> {
        if options.is_undefined() || options.is_null() {
            return Ok(());
        }
        // serde-wasm-bindgen reads only the fields it knows, so misspelt keys are caught here.
        let Some(object) = options.dyn_ref::<js_sys::Object>() else {
            return Err(JsError::new("invalid renderer options: expected an object"));
        };
        for key in js_sys::Object::keys(object).iter() {
            let name = key.as_string().unwrap_or_default();
            OptionsUpdate::check_field(&name).map_err(|e| JsError::new(&format!("invalid renderer options: {e}")))?;
        }
        let update: OptionsUpdate = serde_wasm_bindgen::from_value(options)
            .map_err(|e| JsError::new(&format!("invalid renderer options: {e}")))?;
        self.scene.set_options(&update).map_err(|e| JsError::new(&format!("invalid renderer options: {e}")))
    }

    /// Draws the simulation's newest state. Skips the frame if the surface is not ready
    /// (hidden tab, lost or outdated surface: it is reconfigured for the next frame).
    pub fn render(&mut self, sim: &Simulation) -> Result<(), JsError> {
        self.scene.draw(sim.closed_loop());
        self.present()
    }

    /// Draws two simulations side by side: arm A ("arm") and arm B ("arm-b"), both runs' errors
    /// (and torques) in the same axes — A solid in the usual colours, B thinner in violet (see
    /// `layout().series`) — both runs' poles (B as violet +), and both runs' markers on the maps.
    /// `render(sim)` goes back to the single view.
    #[wasm_bindgen(js_name = renderPair)]
    pub fn render_pair(&mut self, a: &Simulation, b: &Simulation) -> Result<(), JsError> {
        self.scene.draw_pair(a.closed_loop(), b.closed_loop());
        self.present()
    }

    /// Copies a stability map (possibly still being computed) into the picture: `which` is
    /// "off" (the map without preliminary feedback) or "on" (with it). Nothing is recomputed per
    /// frame; call again as more rows arrive.
    #[wasm_bindgen(js_name = setMap)]
    pub fn set_map(&mut self, which: &str, job: &StabilityMapJob) -> Result<(), JsError> {
        let side = MapSide::parse(which).map_err(|e| JsError::new(&format!("setMap: {e}")))?;
        let (deltas, alphas, rho) = job.grid();
        self.scene.set_map(side, deltas, alphas, rho).map_err(|e| JsError::new(&format!("setMap: {e}")))
    }

    /// Forgets both stability maps (their panels show an empty grid until `setMap`).
    #[wasm_bindgen(js_name = clearMaps)]
    pub fn clear_maps(&mut self) {
        self.scene.clear_maps();
    }

    /// The panels for HTML labels over the canvas (CSS pixels, origin top-left of the canvas):
    /// `{panels: [{id: "arm"|"arm-b"|"e1"|"e2"|"torque"|"poles"|"map-off"|"map-on", x, y,
    /// width, height, x_label, y_label, x_range: [a, b], y_range: [lo, hi], x_ticks: [..],
    /// y_ticks: [..], x_scale: "linear"|"log", y_scale}], mode: "single"|"pair",
    /// series: [{run: "A"|"B", color, e1, e2, torque1, torque2, line_width, style, pole_marker,
    /// pole_color, unstable_color, a4_open_color, a4_color}], poles: [{run, kind:
    /// "loop"|"a4_open"|"a4", re, im, zeta, omega, unstable, flexible, x, y, in_view}],
    /// spring_magnification, backend}`. For plots the rectangle is the data area: x_range spans
    /// its width and y_range its height (lo at the bottom), logarithmically where the scale is
    /// "log" (a fraction f of the width is lo·(hi/lo)^f). Ranges and ticks are those of the latest
    /// frame; pole x, y are the markers' centres in CSS pixels.
    pub fn layout(&self) -> Result<JsValue, JsError> {
        let report = LayoutReport {
            panels: self.scene.panel_info(),
            mode: if self.scene.is_pair() { "pair" } else { "single" },
            series: self.scene.series_info(),
            poles: self.scene.pole_info(),
            spring_magnification: self.scene.options().spring_magnification,
            backend: self.backend.name(),
        };
        super::to_js(&report)
    }
}

/// A surface texture ready to draw on.
enum Acquired {
    Good(wgpu::SurfaceTexture),
    /// Usable, but the surface should be reconfigured after presenting.
    Suboptimal(wgpu::SurfaceTexture),
}

impl Renderer {
    /// Uploads the scene's layers and draws them on the next surface texture.
    fn present(&mut self) -> Result<(), JsError> {
        self.upload_static();
        let vertex_count = self.upload_vertices();
        let Some(frame) = self.acquire_frame()? else {
            return Ok(());
        };
        let suboptimal = matches!(frame, Acquired::Suboptimal(_));
        let texture = match frame {
            Acquired::Good(t) | Acquired::Suboptimal(t) => t,
        };
        let view = texture.texture.create_view(&wgpu::TextureViewDescriptor::default());
        let mut encoder =
            self.device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("flexarm frame") });
        {
            let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("flexarm scene"),
                color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                    view: &view,
                    depth_slice: None,
                    resolve_target: None,
                    ops: wgpu::Operations {
                        load: wgpu::LoadOp::Clear(clear_color(self.scene.background(), self.srgb_target)),
                        store: wgpu::StoreOp::Store,
                    },
                })],
                depth_stencil_attachment: None,
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            });
            if self.static_count > 0 || vertex_count > 0 {
                pass.set_pipeline(&self.pipeline);
                pass.set_bind_group(0, &self.bind_group, &[]);
            }
            if self.static_count > 0 {
                pass.set_vertex_buffer(0, self.static_vertices.slice(..));
                pass.draw(0..self.static_count, 0..1);
            }
            if vertex_count > 0 {
                pass.set_vertex_buffer(0, self.vertices.slice(..));
                pass.draw(0..vertex_count, 0..1);
            }
        }
        self.queue.submit([encoder.finish()]);
        self.queue.present(texture);
        if suboptimal {
            self.configure_surface();
        }
        Ok(())
    }

    /// Builds the pipeline and buffers on an opened device.
    fn with_gpu(canvas: HtmlCanvasElement, gpu: Gpu) -> Result<Renderer, JsError> {
        let Gpu { backend, surface, adapter, device, queue } = gpu;
        device.on_uncaptured_error(Arc::new(|e: wgpu::Error| {
            web_sys::console::error_1(&format!("flexarm: graphics error: {e}").into());
        }));
        device.set_device_lost_callback(|reason, message| {
            web_sys::console::error_1(&format!("flexarm: graphics device lost ({reason:?}): {message}").into());
        });

        let (css_width, css_height) = initial_css_size(&canvas);
        let dpr = web_sys::window().map_or(1.0, |w| w.device_pixel_ratio());
        let scene = Scene::new(ViewOptions::default(), css_width, css_height, dpr);
        let (width, height) = scene.physical_size();
        let config = surface_config(&surface, &adapter, width, height).map_err(|e| JsError::new(&e))?;
        let srgb_target = config.format.is_srgb();

        let uniforms = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("flexarm viewport"),
            size: UNIFORM_BYTES,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let bind_group_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("flexarm viewport"),
            entries: &[wgpu::BindGroupLayoutEntry {
                binding: 0,
                visibility: wgpu::ShaderStages::VERTEX | wgpu::ShaderStages::FRAGMENT,
                ty: wgpu::BindingType::Buffer {
                    ty: wgpu::BufferBindingType::Uniform,
                    has_dynamic_offset: false,
                    min_binding_size: wgpu::BufferSize::new(UNIFORM_BYTES),
                },
                count: None,
            }],
        });
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("flexarm viewport"),
            layout: &bind_group_layout,
            entries: &[wgpu::BindGroupEntry { binding: 0, resource: uniforms.as_entire_binding() }],
        });
        let pipeline = create_pipeline(&device, &bind_group_layout, config.format);
        let vertices = create_vertex_buffer(&device, MIN_VERTEX_BUFFER);
        let static_vertices = create_vertex_buffer(&device, MIN_VERTEX_BUFFER);

        let mut renderer = Renderer {
            backend,
            canvas,
            surface,
            device,
            queue,
            config,
            srgb_target,
            pipeline,
            uniforms,
            bind_group,
            vertices,
            static_vertices,
            static_count: 0,
            static_uploaded: None,
            warned_truncation: false,
            scene,
        };
        renderer.apply_size();
        Ok(renderer)
    }

    /// Makes the canvas, the surface and the viewport uniform match the scene's physical size.
    fn apply_size(&mut self) {
        let (width, height) = self.scene.physical_size();
        if self.canvas.width() != width {
            self.canvas.set_width(width);
        }
        if self.canvas.height() != height {
            self.canvas.set_height(height);
        }
        self.config.width = width;
        self.config.height = height;
        self.configure_surface();
        let mut data = [0u8; UNIFORM_BYTES as usize];
        let flag = if self.srgb_target { 1.0f32 } else { 0.0 };
        for (chunk, v) in data.chunks_exact_mut(4).zip([width as f32, height as f32, flag, 0.0]) {
            chunk.copy_from_slice(&v.to_le_bytes());
        }
        self.queue.write_buffer(&self.uniforms, 0, &data);
    }

    fn configure_surface(&self) {
        self.surface.configure(&self.device, &self.config);
    }

    /// Copies the frame's vertices into the GPU buffer (growing it if needed); returns how many
    /// vertices to draw.
    fn upload_vertices(&mut self) -> u32 {
        let bytes = self.scene.painter().vertex_bytes();
        upload(&self.device, &self.queue, &mut self.vertices, bytes, &mut self.warned_truncation)
    }

    /// Uploads the static layer if the scene rebuilt it since the last upload.
    fn upload_static(&mut self) {
        let generation = self.scene.static_generation();
        if self.static_uploaded == Some(generation) {
            return;
        }
        let bytes = self.scene.static_painter().vertex_bytes();
        self.static_count =
            upload(&self.device, &self.queue, &mut self.static_vertices, bytes, &mut self.warned_truncation);
        self.static_uploaded = Some(generation);
    }

    /// The next surface texture, reconfiguring once if the surface is outdated or lost.
    /// `Ok(None)` means: skip this frame.
    fn acquire_frame(&mut self) -> Result<Option<Acquired>, JsError> {
        for attempt in 0..2 {
            match self.surface.get_current_texture() {
                wgpu::CurrentSurfaceTexture::Success(t) => return Ok(Some(Acquired::Good(t))),
                wgpu::CurrentSurfaceTexture::Suboptimal(t) => return Ok(Some(Acquired::Suboptimal(t))),
                wgpu::CurrentSurfaceTexture::Timeout | wgpu::CurrentSurfaceTexture::Occluded => return Ok(None),
                wgpu::CurrentSurfaceTexture::Outdated | wgpu::CurrentSurfaceTexture::Lost => {
                    if attempt == 0 {
                        self.configure_surface();
                    }
                }
                wgpu::CurrentSurfaceTexture::Validation => {
                    return Err(JsError::new(
                        "flexarm: the canvas surface rejected the frame (validation error, see the console)",
                    ));
                }
            }
        }
        warn("flexarm: the canvas surface is still unavailable after reconfiguring; frame skipped");
        Ok(None)
    }
}

/// The canvas' CSS size, or its attribute size when it is not laid out yet.
fn initial_css_size(canvas: &HtmlCanvasElement) -> (f64, f64) {
    let (w, h) = (canvas.client_width(), canvas.client_height());
    if w > 0 && h > 0 {
        (f64::from(w), f64::from(h))
    } else {
        (f64::from(canvas.width().max(1)), f64::from(canvas.height().max(1)))
    }
}

/// WebGPU: adapter and device first, the canvas context last, so that a failure leaves the
/// canvas free for the WebGL2 fallback (a canvas keeps the first context type it gives out).
async fn open_webgpu(canvas: &HtmlCanvasElement) -> Result<Gpu, String> {
    let instance = wgpu::Instance::new(wgpu::InstanceDescriptor {
        backends: wgpu::Backends::BROWSER_WEBGPU,
        ..wgpu::InstanceDescriptor::new_without_display_handle()
    });
    let adapter = instance
        .request_adapter(&wgpu::RequestAdapterOptions::default())
        .await
        .map_err(|e| format!("no adapter: {e}"))?;
    let (device, queue) = request_device(&adapter).await?;
    let surface = instance
        .create_surface(wgpu::SurfaceTarget::Canvas(canvas.clone()))
        .map_err(|e| format!("canvas context: {e}"))?;
    Ok(Gpu { backend: Backend::WebGpu, surface, adapter, device, queue })
}

/// WebGL2 through wgpu's GL backend: the adapter exists only for a surface on the canvas.
async fn open_webgl2(canvas: &HtmlCanvasElement) -> Result<Gpu, String> {
    let instance = wgpu::Instance::new(wgpu::InstanceDescriptor {
        backends: wgpu::Backends::GL,
        ..wgpu::InstanceDescriptor::new_without_display_handle()
    });
    let surface = instance
        .create_surface(wgpu::SurfaceTarget::Canvas(canvas.clone()))
        .map_err(|e| format!("canvas context: {e}"))?;
    let adapter = instance
        .request_adapter(&wgpu::RequestAdapterOptions { compatible_surface: Some(&surface), ..Default::default() })
        .await
        .map_err(|e| format!("no adapter: {e}"))?;
    let (device, queue) = request_device(&adapter).await?;
    Ok(Gpu { backend: Backend::WebGl2, surface, adapter, device, queue })
}

/// A device with WebGL2-level limits (all this renderer needs), raised to the adapter's texture
/// size so large, high-density canvases work.
async fn request_device(adapter: &wgpu::Adapter) -> Result<(wgpu::Device, wgpu::Queue), String> {
    let limits = wgpu::Limits::downlevel_webgl2_defaults().using_resolution(adapter.limits());
    adapter
        .request_device(&wgpu::DeviceDescriptor {
            label: Some("flexarm"),
            required_limits: limits,
            ..Default::default()
        })
        .await
        .map_err(|e| format!("no device: {e}"))
}

/// Surface settings: a non-sRGB format if offered (the colours are sRGB-encoded already), FIFO
/// presentation (vsync) and an opaque canvas.
fn surface_config(
    surface: &wgpu::Surface<'_>,
    adapter: &wgpu::Adapter,
    width: u32,
    height: u32,
) -> Result<wgpu::SurfaceConfiguration, String> {
    let caps = surface.get_capabilities(adapter);
    let format = caps
        .formats
        .iter()
        .copied()
        .find(|f| !f.is_srgb())
        .or_else(|| caps.formats.first().copied())
        .ok_or("the canvas surface offers no texture format this adapter can render to")?;
    let present_mode = if caps.present_modes.contains(&wgpu::PresentMode::Fifo) {
        wgpu::PresentMode::Fifo
    } else {
        wgpu::PresentMode::AutoVsync
    };
    let alpha_mode = if caps.alpha_modes.contains(&wgpu::CompositeAlphaMode::Opaque) {
        wgpu::CompositeAlphaMode::Opaque
    } else {
        caps.alpha_modes.first().copied().unwrap_or(wgpu::CompositeAlphaMode::Auto)
    };
    Ok(wgpu::SurfaceConfiguration {
        usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
        format,
        color_space: wgpu::SurfaceColorSpace::Auto,
        width: width.max(1),
        height: height.max(1),
        present_mode,
        desired_maximum_frame_latency: 2,
        alpha_mode,
        view_formats: Vec::new(),
    })
}

fn create_pipeline(
    device: &wgpu::Device,
    bind_group_layout: &wgpu::BindGroupLayout,
    format: wgpu::TextureFormat,
) -> wgpu::RenderPipeline {
    let shader = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("flexarm shader"),
        source: wgpu::ShaderSource::Wgsl(SHADER.into()),
    });
    let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
        label: Some("flexarm"),
        bind_group_layouts: &[Some(bind_group_layout)],
        immediate_size: 0,
    });
    let attributes = [
        wgpu::VertexAttribute { format: wgpu::VertexFormat::Float32x2, offset: 0, shader_location: 0 },
        wgpu::VertexAttribute {
            format: wgpu::VertexFormat::Float32x4,
            offset: Vertex::COLOR_OFFSET as u64,
            shader_location: 1,
        },
    ];
    device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some("flexarm triangles"),
        layout: Some(&layout),
        vertex: wgpu::VertexState {
            module: &shader,
            entry_point: Some("vs_main"),
            compilation_options: Default::default(),
            buffers: &[Some(wgpu::VertexBufferLayout {
                array_stride: Vertex::SIZE as u64,
                step_mode: wgpu::VertexStepMode::Vertex,
                attributes: &attributes,
            })],
        },
        primitive: wgpu::PrimitiveState {
            topology: wgpu::PrimitiveTopology::TriangleList,
            // Tessellation does not keep a consistent winding; draw both faces.
            cull_mode: None,
            ..Default::default()
        },
        depth_stencil: None,
        multisample: wgpu::MultisampleState::default(),
        fragment: Some(wgpu::FragmentState {
            module: &shader,
            entry_point: Some("fs_main"),
            compilation_options: Default::default(),
            targets: &[Some(wgpu::ColorTargetState {
                format,
                blend: Some(wgpu::BlendState::ALPHA_BLENDING),
                write_mask: wgpu::ColorWrites::ALL,
            })],
        }),
        multiview_mask: None,
        cache: None,
    })
}

/// Copies `bytes` (whole vertices) into `buffer`, replacing it with a larger one if needed;
/// returns how many vertices to draw. Beyond the device's buffer limit whole triangles are
/// dropped and a warning is logged once.
fn upload(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    buffer: &mut wgpu::Buffer,
    bytes: &[u8],
    warned_truncation: &mut bool,
) -> u32 {
    let max_buffer = device.limits().max_buffer_size;
    let mut len = bytes.len() as u64;
    if len > max_buffer {
        // Keep whole triangles that fit; this needs an absurdly large canvas.
        let triangle = 3 * Vertex::SIZE as u64;
        len = max_buffer / triangle * triangle;
        if !*warned_truncation {
            warn("flexarm: the frame has more triangles than one GPU buffer holds; some are not drawn");
            *warned_truncation = true;
        }
    }
    if len > buffer.size() {
        let size = len.next_power_of_two().clamp(MIN_VERTEX_BUFFER, max_buffer.max(MIN_VERTEX_BUFFER));
        *buffer = create_vertex_buffer(device, size);
    }
    if len > 0 {
        queue.write_buffer(buffer, 0, &bytes[..len as usize]);
    }
    u32::try_from(len / Vertex::SIZE as u64).unwrap_or(u32::MAX)
}

fn create_vertex_buffer(device: &wgpu::Device, size: u64) -> wgpu::Buffer {
    device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("flexarm vertices"),
        size,
        usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    })
}

/// The clear colour; linear when the target is sRGB (the GPU encodes it on write).
fn clear_color(c: Color, srgb_target: bool) -> wgpu::Color {
    let decode = |v: f64| {
        if !srgb_target {
            v
        } else if v <= 0.04045 {
            v / 12.92
        } else {
            ((v + 0.055) / 1.055).powf(2.4)
        }
    };
    let [r, g, b, a] = c.to_f64();
    wgpu::Color { r: decode(r), g: decode(g), b: decode(b), a }
}
