// flexarm's one shader: the view's triangles arrive in physical pixels with sRGB-encoded colours;
// the vertex stage maps pixels to clip space, the fragment stage passes the colour through
// (its lightness inverted in the dark scheme; decoded to linear first when the surface encodes
// sRGB on write).

struct Viewport {
    // Canvas size in physical pixels.
    size: vec2<f32>,
    // 1.0 if the target encodes sRGB on write (colours must be decoded first), else 0.0.
    srgb_target: f32,
    // 1.0 for the dark colour scheme: every colour's lightness inverted (Color::for_dark).
    dark: f32,
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

// Lightness inverted, hue and chroma kept: every channel moves by 1 − max − min.
fn for_dark(c: vec3<f32>) -> vec3<f32> {
    let shift = 1.0 - max(c.r, max(c.g, c.b)) - min(c.r, min(c.g, c.b));
    return c + vec3<f32>(shift);
}

@fragment
fn fs_main(in: VertexOutput) -> @location(0) vec4<f32> {
    var rgb = in.color.rgb;
    if (viewport.dark > 0.5) {
        rgb = for_dark(rgb);
    }
    if (viewport.srgb_target > 0.5) {
        rgb = srgb_to_linear(rgb);
    }
    return vec4<f32>(rgb, in.color.a);
}
