//! What the page draws, as plain geometry with no GPU or web types (so it is testable natively):
//! panels laid out in CSS pixels, tessellated into coloured triangles that the wgpu renderer in
//! `web` uploads as they are.
