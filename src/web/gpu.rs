//! The GPU side of the renderer, as thin as it can be: a device and a surface on the canvas
//! (WebGPU when the browser offers an adapter, WebGL2 otherwise), one pipeline that draws
//! coloured triangles in physical pixels ([`shader.wgsl`](../shader.wgsl), handed to wgpu as
//! the naga IR that build.rs writes from it), and two vertex
//! buffers reused from frame to frame — the static layer (uploaded only when it changes) and the
//! per-frame layer drawn over it. It knows nothing of what the triangles show.

use std::sync::Arc;

use wasm_bindgen::JsError;
use web_sys::HtmlCanvasElement;

use crate::view::{Color, Vertex};

/// The shader: `shader.wgsl`, parsed at build time into the Rust that builds its naga IR
/// (build.rs), so the page needs no WGSL parser.
mod shader_ir {
    include!(concat!(env!("OUT_DIR"), "/shader_ir.rs"));
}
/// Size of the uniform block: vec2 size, f32 sRGB flag, f32 dark flag.
const UNIFORM_BYTES: u64 = 16;
/// Smallest vertex buffer allocated, bytes.
const MIN_VERTEX_BUFFER: u64 = 256 * 1024;

/// Which browser graphics API draws.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Backend {
    WebGpu,
    WebGl2,
}

impl Backend {
    pub fn name(self) -> &'static str {
        match self {
            Backend::WebGpu => "WebGPU",
            Backend::WebGl2 => "WebGL2",
        }
    }
}

pub(crate) fn log(message: &str) {
    web_sys::console::log_1(&message.into());
}

pub(crate) fn warn(message: &str) {
    web_sys::console::warn_1(&message.into());
}

/// The device and surface of one backend.
struct Device {
    backend: Backend,
    surface: wgpu::Surface<'static>,
    adapter: wgpu::Adapter,
    device: wgpu::Device,
    queue: wgpu::Queue,
}

/// A canvas the GPU draws triangle lists on.
pub struct GpuCanvas {
    backend: Backend,
    canvas: HtmlCanvasElement,
    surface: wgpu::Surface<'static>,
    device: wgpu::Device,
    queue: wgpu::Queue,
    config: wgpu::SurfaceConfiguration,
    /// True if the surface format is sRGB (the shader then decodes colours).
    srgb_target: bool,
    /// The dark colour scheme: every colour's lightness inverted.
    dark: bool,
    pipeline: wgpu::RenderPipeline,
    uniforms: wgpu::Buffer,
    bind_group: wgpu::BindGroup,
    vertices: wgpu::Buffer,
    /// The static layer, drawn before `vertices`.
    static_vertices: wgpu::Buffer,
    /// Vertices in `static_vertices`, and the generation they came from.
    static_count: u32,
    static_uploaded: Option<u64>,
    /// Set once a frame had more vertices than the device allows in one buffer.
    warned_truncation: bool,
}

impl GpuCanvas {
    /// Opens WebGPU when `navigator.gpu` yields an adapter, WebGL2 otherwise; logs the choice.
    /// Fails with a readable message if neither works.
    pub async fn open(canvas: HtmlCanvasElement, width: u32, height: u32) -> Result<GpuCanvas, JsError> {
        let mut failures: Vec<String> = Vec::new();
        let mut device = None;
        if wgpu::util::is_browser_webgpu_supported().await {
            match open_webgpu(&canvas).await {
                Ok(d) => device = Some(d),
                Err(e) => {
                    warn(&format!("flexarm: WebGPU is offered but could not be used ({e}); trying WebGL2"));
                    failures.push(format!("WebGPU: {e}"));
                }
            }
        } else {
            failures.push("WebGPU: navigator.gpu is missing or gives no adapter".into());
        }
        if device.is_none() {
            match open_webgl2(&canvas).await {
                Ok(d) => device = Some(d),
                Err(e) => failures.push(format!("WebGL2: {e}")),
            }
        }
        let Some(device) = device else {
            return Err(JsError::new(&format!(
                "flexarm cannot draw: neither WebGPU nor WebGL2 is available in this browser ({}). \
                 Try a current Chrome, Edge or Firefox with hardware acceleration enabled.",
                failures.join("; ")
            )));
        };
        let info = device.adapter.get_info();
        let on = if info.name.is_empty() { String::new() } else { format!(" on {}", info.name) };
        log(&format!("flexarm: drawing with {}{on}", device.backend.name()));
        Self::with_device(canvas, device, width, height)
    }

    pub fn backend(&self) -> Backend {
        self.backend
    }

    /// The largest texture side the device allows, pixels.
    pub fn max_texture_side(&self) -> u32 {
        self.device.limits().max_texture_dimension_2d.max(1)
    }

    fn with_device(canvas: HtmlCanvasElement, d: Device, width: u32, height: u32) -> Result<GpuCanvas, JsError> {
        let Device { backend, surface, adapter, device, queue } = d;
        device.on_uncaptured_error(Arc::new(|e: wgpu::Error| {
            web_sys::console::error_1(&format!("flexarm: graphics error: {e}").into());
        }));
        device.set_device_lost_callback(|reason, message| {
            web_sys::console::error_1(&format!("flexarm: graphics device lost ({reason:?}): {message}").into());
        });
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
        let mut gpu = GpuCanvas {
            backend,
            canvas,
            surface,
            device,
            queue,
            config,
            srgb_target,
            dark: false,
            pipeline,
            uniforms,
            bind_group,
            vertices,
            static_vertices,
            static_count: 0,
            static_uploaded: None,
            warned_truncation: false,
        };
        gpu.resize(width, height);
        Ok(gpu)
    }

    /// Makes the canvas, the surface and the viewport uniform `width × height` physical pixels.
    pub fn resize(&mut self, width: u32, height: u32) {
        if self.canvas.width() != width {
            self.canvas.set_width(width);
        }
        if self.canvas.height() != height {
            self.canvas.set_height(height);
        }
        self.config.width = width.max(1);
        self.config.height = height.max(1);
        self.configure_surface();
        self.write_uniforms();
    }

    /// Draws in the dark colour scheme (lightness inverted) or not.
    pub fn set_dark(&mut self, dark: bool) {
        self.dark = dark;
        self.write_uniforms();
    }

    fn write_uniforms(&self) {
        let flag = |b: bool| if b { 1.0f32 } else { 0.0 };
        let data: [f32; 4] =
            [self.config.width as f32, self.config.height as f32, flag(self.srgb_target), flag(self.dark)];
        self.queue.write_buffer(&self.uniforms, 0, bytemuck::cast_slice(&data));
    }

    fn configure_surface(&self) {
        self.surface.configure(&self.device, &self.config);
    }

    /// Draws the static layer (uploaded again only when `static_generation` changed) and then
    /// the frame's vertices over it, on a cleared canvas. Skips the frame if the surface is not
    /// ready (hidden tab, lost or outdated surface: it is reconfigured for the next frame).
    pub fn draw(
        &mut self,
        background: Color,
        static_vertices: &[Vertex],
        static_generation: u64,
        vertices: &[Vertex],
    ) -> Result<(), JsError> {
        if self.static_uploaded != Some(static_generation) {
            self.static_count = upload(
                &self.device,
                &self.queue,
                &mut self.static_vertices,
                bytemuck::cast_slice(static_vertices),
                &mut self.warned_truncation,
            );
            self.static_uploaded = Some(static_generation);
        }
        let vertex_count = upload(
            &self.device,
            &self.queue,
            &mut self.vertices,
            bytemuck::cast_slice(vertices),
            &mut self.warned_truncation,
        );
        let Some((texture, suboptimal)) = self.acquire_frame()? else {
            return Ok(());
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
                        load: wgpu::LoadOp::Clear(clear_color(
                            if self.dark { background.for_dark() } else { background },
                            self.srgb_target,
                        )),
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

    /// The next surface texture (and whether the surface wants reconfiguring after it),
    /// reconfiguring once if the surface is outdated or lost. `Ok(None)` means: skip this frame.
    fn acquire_frame(&mut self) -> Result<Option<(wgpu::SurfaceTexture, bool)>, JsError> {
        for attempt in 0..2 {
            match self.surface.get_current_texture() {
                wgpu::CurrentSurfaceTexture::Success(t) => return Ok(Some((t, false))),
                wgpu::CurrentSurfaceTexture::Suboptimal(t) => return Ok(Some((t, true))),
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

/// WebGPU: adapter and device first, the canvas context last, so that a failure leaves the
/// canvas free for the WebGL2 fallback (a canvas keeps the first context type it gives out).
async fn open_webgpu(canvas: &HtmlCanvasElement) -> Result<Device, String> {
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
    Ok(Device { backend: Backend::WebGpu, surface, adapter, device, queue })
}

/// WebGL2 through wgpu's GL backend: the adapter exists only for a surface on the canvas.
async fn open_webgl2(canvas: &HtmlCanvasElement) -> Result<Device, String> {
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
    Ok(Device { backend: Backend::WebGl2, surface, adapter, device, queue })
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
        source: wgpu::ShaderSource::Naga(std::borrow::Cow::Owned(shader_ir::module())),
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
