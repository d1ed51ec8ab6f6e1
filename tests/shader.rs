//! The shader the page hands wgpu is `src/web/shader.wgsl`: build.rs turns the file into Rust
//! that builds its naga IR (so the page ships no WGSL parser). Here that IR is checked against a
//! parse of the same file: it must be valid, and the GLSL ES 3.0 that WebGL2 compiles must be the
//! same text, stage by stage, as naga writes from the WGSL itself.

use naga::back::glsl;
use naga::valid::{Capabilities, ModuleInfo, ValidationFlags, Validator};
use naga::{Module, ShaderStage};

mod shader_ir {
    include!(concat!(env!("OUT_DIR"), "/shader_ir.rs"));
}

const WGSL: &str = include_str!("../src/web/shader.wgsl");

fn validate(module: &Module) -> ModuleInfo {
    Validator::new(ValidationFlags::all(), Capabilities::empty())
        .validate(module)
        .unwrap_or_else(|e| panic!("the module does not validate: {e:?}"))
}

/// What WebGL2 receives for one stage: GLSL ES 3.0, as wgpu's GL backend asks naga for it.
fn glsl(module: &Module, info: &ModuleInfo, stage: ShaderStage, entry_point: &str) -> String {
    let options =
        glsl::Options { version: glsl::Version::Embedded { version: 300, is_webgl: true }, ..Default::default() };
    let pipeline = glsl::PipelineOptions { shader_stage: stage, entry_point: entry_point.into(), multiview: None };
    let mut out = String::new();
    let mut writer = glsl::Writer::new(&mut out, module, info, &options, &pipeline, Default::default())
        .unwrap_or_else(|e| panic!("no GLSL writer for {entry_point}: {e:?}"));
    writer.write().unwrap_or_else(|e| panic!("no GLSL for {entry_point}: {e:?}"));
    out
}

#[test]
fn the_built_ir_is_the_wgsl_files() {
    let parsed = naga::front::wgsl::parse_str(WGSL).expect("shader.wgsl parses");
    let built = shader_ir::module();
    let (parsed_info, built_info) = (validate(&parsed), validate(&built));
    assert_eq!(built.entry_points.len(), parsed.entry_points.len());
    for (stage, name) in [(ShaderStage::Vertex, "vs_main"), (ShaderStage::Fragment, "fs_main")] {
        assert!(built.entry_points.iter().any(|e| e.stage == stage && e.name == name), "no {name} in the IR");
        let want = glsl(&parsed, &parsed_info, stage, name);
        let got = glsl(&built, &built_info, stage, name);
        assert_eq!(got, want, "{name}: the GLSL from the built IR differs from the GLSL of shader.wgsl");
        // Not an empty agreement: the stage does what the file says.
        let must = if stage == ShaderStage::Vertex { "gl_Position" } else { "pow(" };
        assert!(got.contains(must), "{name} has no {must}:\n{got}");
    }
}
