//! Shader variants: the scene's pipelines compiled for one feature set, so that a pixel pays
//! nothing for what is not in the pool. Software rasterisers (SwiftShader in a browser
//! without a GPU, lavapipe) run both sides of every branch, so a uniform "is there a duck"
//! test still costs the duck's ray tests; a constant written into the source lets the shader
//! compiler drop them. The constants come from [`Features::wgsl`]; pipelines are built the
//! first time a feature set is drawn and kept ([`PoolPasses`](super::PoolPasses) caches them).

use super::shaders;
use crate::bodies::BodyId;
use crate::gpu;
use crate::render::scene_parts::{mesh_pipeline, DepthUse, MeshPipeline};
use crate::render::Features;

/// The pipelines of the passes that read the scene's features: the caustics map and the
/// water surface, pool, sphere and duck of the scene pass.
pub struct ScenePipelines {
    /// The caustics map's draw, or with dispersion one per colour channel (red, green with
    /// alpha, blue), each writing only its channels.
    pub caustics: Vec<wgpu::RenderPipeline>,
    pub surface: wgpu::RenderPipeline,
    pub pool: wgpu::RenderPipeline,
    /// The deck around the pool (the pool's shader types and its own fragment shader).
    pub deck: wgpu::RenderPipeline,
    /// Per kind of `bodies::KINDS`, its mesh's pipeline, if the kind is among the features'.
    pub bodies: Vec<Option<wgpu::RenderPipeline>>,
    /// Per kind, its outline's pipeline (`BodyKind::edge`), if it has one and is among the
    /// features' (not in the flat water's textures).
    pub edges: Vec<Option<wgpu::RenderPipeline>>,
}

/// Formats and layouts the scene's pipelines are built for (fixed for a renderer).
pub struct PipelineTargets<'a> {
    /// Colour target of the scene pass.
    pub format: wgpu::TextureFormat,
    pub caustics_format: wgpu::TextureFormat,
    /// Scene uniforms + water state (group 0).
    pub water_layout: &'a wgpu::BindGroupLayout,
    /// Scene textures (group 1).
    pub textures_layout: &'a wgpu::BindGroupLayout,
}

/// A variant's pipelines built one at a time: each compiles a shader, 20 to 60 ms of a
/// browser's main thread on WebGL2 without a GPU, so a start-up that must not hold the thread
/// for long builds one per task ([`super::PoolPasses::build_ahead`]).
pub struct VariantBuild {
    features: Features,
    prelude: String,
    caustics: Option<Vec<wgpu::RenderPipeline>>,
    surface: Option<wgpu::RenderPipeline>,
    pool: Option<wgpu::RenderPipeline>,
    deck: Option<wgpu::RenderPipeline>,
    /// Per kind of `bodies::KINDS`, once looked at: its pipeline if the kind is among the
    /// features'.
    bodies: Vec<Option<wgpu::RenderPipeline>>,
    /// The same for the kinds' outlines.
    edges: Vec<Option<wgpu::RenderPipeline>>,
}

impl VariantBuild {
    /// `target`: the scene's final colour format (see `shaders::scene_prelude`).
    pub fn new(features: Features, target: wgpu::TextureFormat) -> Self {
        Self {
            features,
            prelude: shaders::scene_prelude(features, target),
            caustics: None,
            surface: None,
            pool: None,
            deck: None,
            bodies: Vec::new(),
            edges: Vec::new(),
        }
    }

    /// Builds the next pipeline not built yet; true once there is none left.
    pub fn step(&mut self, device: &wgpu::Device, targets: &PipelineTargets<'_>) -> bool {
        let (features, prelude) = (self.features, self.prelude.as_str());
        let module = |label, part| gpu::shader(device, label, &[prelude, part]);
        let pool_attributes = &wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3];
        let back = Some(wgpu::Face::Back);
        let scene = |label: &str, module: &wgpu::ShaderModule, vs: &str, fs: &str, attributes, stride, cull| {
            let part = ScenePart {
                label,
                module,
                entries: [vs, fs],
                vertex: (attributes, stride),
                cull,
                overlay: false,
                blended: false,
            };
            scene_pipeline(device, features, targets, part)
        };
        if self.caustics.is_none() {
            self.caustics = Some(caustics_pipelines(device, features, targets, prelude));
        } else if self.surface.is_none() {
            // Culling off: front faces are the surface seen from above, back faces from below.
            let attributes = &wgpu::vertex_attr_array![0 => Float32x2];
            let module = module("water surface", shaders::WATER);
            // With bodies the surface is blended by its alpha: the share of a pixel it covers
            // at a waterline, over the body drawn before (1 elsewhere).
            let part = ScenePart {
                label: "water surface",
                module: &module,
                entries: ["vs_surface", "fs_surface"],
                vertex: (attributes, 8),
                cull: None,
                overlay: false,
                blended: features.bodies != 0,
            };
            self.surface = Some(scene_pipeline(device, features, targets, part));
        } else if self.pool.is_none() {
            let module = module("pool", shaders::POOL);
            self.pool = Some(scene("pool", &module, "vs_pool", "fs_pool", pool_attributes, 24, back));
        } else if self.deck.is_none() {
            let module = module("deck", &[shaders::POOL, shaders::DECK].concat());
            self.deck = Some(scene("deck", &module, "vs_pool", "fs_deck", pool_attributes, 24, back));
        } else if self.bodies.len() < BodyId::all().count() {
            // The next kind of body in the features (the others get no pipeline).
            while let Some(id) = BodyId::all().nth(self.bodies.len()) {
                let present = features.bodies & id.bit() as u8 != 0;
                self.bodies.push(present.then(|| {
                    let kind = id.kind();
                    let (vs, fs) = (format!("vs_{}", kind.name), format!("fs_{}", kind.name));
                    let module = module(kind.name, "");
                    scene(kind.name, &module, &vs, &fs, kind.vertex, kind.vertex_stride, back)
                }));
                if present {
                    break;
                }
            }
        } else {
            // The next present kind's outline, if it has one.
            while let Some(id) = BodyId::all().nth(self.edges.len()) {
                let kind = id.kind();
                let present = features.bodies & id.bit() as u8 != 0 && kind.edge && features.clip == 0;
                self.edges.push(present.then(|| {
                    let (vs, fs) = (format!("vs_{}_edge", kind.name), format!("fs_{}_edge", kind.name));
                    let module = module(kind.name, "");
                    let (attributes, stride) = (kind.vertex, kind.vertex_stride);
                    let part = ScenePart {
                        label: "outline",
                        module: &module,
                        entries: [&vs, &fs],
                        vertex: (attributes, stride),
                        cull: back,
                        overlay: true,
                        blended: true,
                    };
                    scene_pipeline(device, features, targets, part)
                }));
                if present {
                    break;
                }
            }
        }
        self.edges.len() == BodyId::all().count()
    }

    /// The variant's pipelines, building what is left.
    pub fn finish(mut self, device: &wgpu::Device, targets: &PipelineTargets<'_>) -> ScenePipelines {
        while !self.step(device, targets) {}
        let built = "a finished variant has every pipeline";
        ScenePipelines {
            caustics: self.caustics.expect(built),
            surface: self.surface.expect(built),
            pool: self.pool.expect(built),
            deck: self.deck.expect(built),
            bodies: self.bodies,
            edges: self.edges,
        }
    }
}

/// A pipeline of the scene pass: its label and shader module, its vertex and fragment entry
/// points, the mesh's attributes and stride (bytes), its culling; a blended part is blended by
/// its alpha over what is drawn, and an overlay (blended) also leaves the depth as it is.
struct ScenePart<'a> {
    label: &'a str,
    module: &'a wgpu::ShaderModule,
    entries: [&'a str; 2],
    vertex: (&'a [wgpu::VertexAttribute], u64),
    cull: Option<wgpu::Face>,
    overlay: bool,
    blended: bool,
}

/// `part`'s pipeline for `features`.
fn scene_pipeline(
    device: &wgpu::Device,
    features: Features,
    targets: &PipelineTargets<'_>,
    part: ScenePart<'_>,
) -> wgpu::RenderPipeline {
    let ScenePart { label, module, entries, vertex, cull, overlay, blended } = part;
    // The mirrored camera (the flat water's reflection) turns every triangle's winding over.
    let front_face = if features.clip > 0 { wgpu::FrontFace::Cw } else { wgpu::FrontFace::Ccw };
    mesh_pipeline(
        device,
        MeshPipeline {
            label,
            module,
            vertex_entry: entries[0],
            fragment_entry: entries[1],
            layouts: &[targets.water_layout, targets.textures_layout],
            attributes: vertex.0,
            stride: vertex.1,
            cull,
            front_face,
            format: targets.format,
            blend: blended.then_some(wgpu::BlendState::ALPHA_BLENDING),
            write_mask: wgpu::ColorWrites::ALL,
            depth: if overlay { DepthUse::Test } else { DepthUse::TestAndWrite },
        },
    )
}

/// The caustics map's pipelines for `features`: one, or with dispersion one per colour channel
/// (each refracting by its own index), adding their light into the map.
fn caustics_pipelines(
    device: &wgpu::Device,
    features: Features,
    targets: &PipelineTargets<'_>,
    prelude: &str,
) -> Vec<wgpu::RenderPipeline> {
    let additive = wgpu::BlendComponent {
        src_factor: wgpu::BlendFactor::One,
        dst_factor: wgpu::BlendFactor::One,
        operation: wgpu::BlendOperation::Add,
    };
    // CAUSTICS_CHANNEL: the colour whose index of refraction a draw uses (with dispersion).
    let channels: &[(i32, wgpu::ColorWrites)] = if features.dispersion {
        &[
            (0, wgpu::ColorWrites::RED),
            (1, wgpu::ColorWrites::GREEN.union(wgpu::ColorWrites::ALPHA)),
            (2, wgpu::ColorWrites::BLUE),
        ]
    } else {
        &[(1, wgpu::ColorWrites::ALL)]
    };
    channels
        .iter()
        .map(|&(channel, write_mask)| {
            let channel_constant = format!("const CAUSTICS_CHANNEL: i32 = {channel};\n");
            let caustics_module = gpu::shader(device, "caustics", &[&channel_constant, prelude, shaders::CAUSTICS]);
            mesh_pipeline(
                device,
                MeshPipeline {
                    label: "caustics",
                    module: &caustics_module,
                    vertex_entry: "vs_caustics",
                    fragment_entry: "fs_caustics",
                    layouts: &[targets.water_layout],
                    attributes: &wgpu::vertex_attr_array![0 => Float32x2],
                    stride: 8,
                    cull: None,
                    front_face: wgpu::FrontFace::Ccw,
                    format: targets.caustics_format,
                    blend: Some(wgpu::BlendState { color: additive, alpha: additive }),
                    write_mask,
                    depth: DepthUse::None,
                },
            )
        })
        .collect()
}
