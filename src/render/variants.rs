//! Shader variants: the scene's pipelines compiled for one feature set, so that a pixel pays
//! nothing for what is not in the pool. Software rasterisers (SwiftShader in a browser
//! without a GPU, lavapipe) run both sides of every branch, so a uniform "is there a duck"
//! test still costs the duck's ray tests; a constant written into the source lets the shader
//! compiler drop them. The constants come from [`Features::wgsl`]; pipelines are built the
//! first time a feature set is drawn and kept ([`Renderer`](super::Renderer) caches them).

use glam::{Vec3, Vec4Swizzles};

use super::{View, DEPTH_FORMAT};
use crate::{duck, gpu};

/// What a frame shows that costs shader work: the shader constants of a variant.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Features {
    /// The sphere is in the pool (traced in reflections and refractions, casts shadows).
    pub sphere: bool,
    /// The duck is in the pool.
    pub duck: bool,
    /// Light under water comes from the caustics map (else from a calm surface).
    pub caustics: bool,
}

impl Features {
    pub fn of(view: &View) -> Self {
        Self { sphere: view.sphere.is_some(), duck: view.duck.is_some(), caustics: view.caustics }
    }

    /// The WGSL constants that select this variant (`HAS_SPHERE`, `HAS_DUCK`, `HAS_CAUSTICS`).
    pub fn wgsl(&self) -> String {
        format!(
            "const HAS_SPHERE: bool = {};\nconst HAS_DUCK: bool = {};\nconst HAS_CAUSTICS: bool = {};\n",
            self.sphere, self.duck, self.caustics
        )
    }
}

/// Margin around an object's region of the water surface, as a fraction of the region's
/// larger side, plus [`REGION_MARGIN_PX`]: waves tilt the surface and bend what it shows by
/// a distance that grows with the distance between the object and the surface it is seen
/// in, which is about the object's size.
const REGION_MARGIN: f32 = 0.25;
const REGION_MARGIN_PX: f32 = 4.0;
/// Above this share of the target the region is not worth a second set of draws.
const REGION_MAX_SHARE: f32 = 0.5;

impl Features {
    /// The same without the objects.
    pub fn without_objects(self) -> Self {
        Self { sphere: false, duck: false, ..self }
    }
}

/// Where the water surface must show the objects, for a `size` target: after the surface is
/// drawn whole by the variant without objects, each rectangle (x, y, width, height in pixels)
/// is drawn over again, in order, by the variant with the objects it can show. With the camera
/// above the water an object can be seen, reflected or refracted, only near the screen bound
/// of the column from the surface down to the bottom of the object or of its mirror image,
/// grown by [`REGION_MARGIN`]; where two such rectangles overlap, a last one shows both.
/// `None`: draw the whole surface with every object (the camera under water, or rectangles too
/// large to gain from). Software rasterisers pay per triangle as well as per pixel, hence a
/// few overdrawn rectangles rather than a tiling of the screen.
pub fn surface_overlays(view: &View, size: (u32, u32)) -> Option<Vec<([u32; 4], Features)>> {
    let plain = Features::of(view).without_objects();
    let mut bounds: Vec<(Vec3, f32, Features)> = Vec::new();
    bounds.extend(view.sphere.map(|s| (s.centre, s.radius, Features { sphere: true, ..plain })));
    bounds.extend(view.duck.map(|p| (p.position, duck::bounding_radius(), Features { duck: true, ..plain })));
    if view.eye.y < 0.0 {
        return None;
    }
    let (w, h) = (size.0 as f32, size.1 as f32);
    // Rectangles as (x0, y0, x1, y1).
    let mut rects: Vec<([u32; 4], Features)> = Vec::new();
    for (centre, radius, with) in bounds {
        let (mut lo, mut hi) = (glam::Vec2::splat(f32::INFINITY), glam::Vec2::splat(f32::NEG_INFINITY));
        // From above, the surface shows what is under water refracted (raised towards the
        // surface, straight above itself) and what is above it mirrored: both within the
        // column over the object, from the surface down to its own or its mirror image's bottom.
        let bottom = -(centre.y.abs() + radius);
        for corner in 0..8 {
            let pick = |bit: u32, a: f32, b: f32| if corner & bit == 0 { a } else { b };
            let p = Vec3::new(
                pick(1, centre.x - radius, centre.x + radius),
                pick(2, bottom, 0.0),
                pick(4, centre.z - radius, centre.z + radius),
            );
            let clip = view.view_proj * p.extend(1.0);
            if clip.w <= 1e-3 {
                return None;
            }
            lo = lo.min(clip.xy() / clip.w);
            hi = hi.max(clip.xy() / clip.w);
        }
        // NDC (y up) to pixels (y down), with the margin.
        let (x0, x1) = ((lo.x * 0.5 + 0.5) * w, (hi.x * 0.5 + 0.5) * w);
        let (y0, y1) = ((0.5 - hi.y * 0.5) * h, (0.5 - lo.y * 0.5) * h);
        let margin = REGION_MARGIN * (x1 - x0).max(y1 - y0) + REGION_MARGIN_PX;
        let pixel = |v: f32, end: f32| v.round().clamp(0.0, end) as u32;
        let rect = [pixel(x0 - margin, w), pixel(y0 - margin, h), pixel(x1 + margin, w), pixel(y1 + margin, h)];
        if rect[2] > rect[0] && rect[3] > rect[1] {
            rects.push((rect, with));
        }
    }
    let overlays = with_overlaps(rects);
    let area = |r: &[u32; 4]| r[2] * r[3];
    let covered: i64 =
        overlays.iter().map(|(r, f)| if f.sphere && f.duck { -(area(r) as i64) } else { area(r) as i64 }).sum();
    (covered as f32 <= REGION_MAX_SHARE * w * h).then_some(overlays)
}

/// The rectangles (x0, y0, x1, y1, each with its features) as (x, y, width, height), followed
/// by the overlap of each pair with the features of both.
fn with_overlaps(rects: Vec<([u32; 4], Features)>) -> Vec<([u32; 4], Features)> {
    let mut out: Vec<([u32; 4], Features)> = Vec::new();
    for (i, (a, fa)) in rects.iter().enumerate() {
        out.push(([a[0], a[1], a[2] - a[0], a[3] - a[1]], *fa));
        for (b, fb) in &rects[..i] {
            let (x0, y0, x1, y1) = (a[0].max(b[0]), a[1].max(b[1]), a[2].min(b[2]), a[3].min(b[3]));
            if x1 > x0 && y1 > y0 {
                let both = Features { sphere: fa.sphere || fb.sphere, duck: fa.duck || fb.duck, ..*fa };
                out.push(([x0, y0, x1 - x0, y1 - y0], both));
            }
        }
    }
    // Overlaps last, over both of their rectangles.
    out.sort_by_key(|(_, f)| f.sphere && f.duck);
    out
}

/// The pipelines of the passes that read the scene's features: the caustics map and the
/// water surface, pool, sphere and duck of the scene pass.
pub struct ScenePipelines {
    pub caustics: wgpu::RenderPipeline,
    pub surface: wgpu::RenderPipeline,
    pub pool: wgpu::RenderPipeline,
    pub sphere: wgpu::RenderPipeline,
    pub duck: wgpu::RenderPipeline,
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

impl ScenePipelines {
    pub fn new(device: &wgpu::Device, features: Features, targets: &PipelineTargets<'_>) -> Self {
        let constants = features.wgsl();
        let module = |label, part| gpu::shader(device, label, &[&constants, gpu::wgsl::COMMON, gpu::wgsl::SCENE, part]);
        let caustics_module = module("caustics", gpu::wgsl::CAUSTICS);
        let additive = wgpu::BlendComponent {
            src_factor: wgpu::BlendFactor::One,
            dst_factor: wgpu::BlendFactor::One,
            operation: wgpu::BlendOperation::Add,
        };
        let caustics = mesh_pipeline(
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
                format: targets.caustics_format,
                blend: Some(wgpu::BlendState { color: additive, alpha: additive }),
                depth: None,
            },
        );
        let layouts = [targets.water_layout, targets.textures_layout];
        let scene_pipeline =
            |label, module: &wgpu::ShaderModule, vs, fs, attributes: &[wgpu::VertexAttribute], stride, cull, depth| {
                mesh_pipeline(
                    device,
                    MeshPipeline {
                        label,
                        module,
                        vertex_entry: vs,
                        fragment_entry: fs,
                        layouts: &layouts,
                        attributes,
                        stride,
                        cull,
                        format: targets.format,
                        blend: None,
                        depth: Some(depth),
                    },
                )
            };
        let back = Some(wgpu::Face::Back);
        Self {
            caustics,
            // Culling off: front faces are the surface seen from above, back faces from below.
            surface: scene_pipeline(
                "water surface",
                &module("water surface", gpu::wgsl::WATER),
                "vs_surface",
                "fs_surface",
                &wgpu::vertex_attr_array![0 => Float32x2],
                8,
                None,
                // Equal passes: the objects' rectangles are drawn again over the whole surface.
                wgpu::CompareFunction::LessEqual,
            ),
            pool: scene_pipeline(
                "pool",
                &module("pool", gpu::wgsl::POOL),
                "vs_pool",
                "fs_pool",
                &wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3],
                24,
                back,
                wgpu::CompareFunction::Less,
            ),
            sphere: scene_pipeline(
                "sphere",
                &module("sphere", gpu::wgsl::SPHERE),
                "vs_sphere",
                "fs_sphere",
                &wgpu::vertex_attr_array![0 => Float32x3],
                12,
                back,
                wgpu::CompareFunction::Less,
            ),
            duck: scene_pipeline(
                "duck",
                &module("duck", gpu::wgsl::DUCK),
                "vs_duck",
                "fs_duck",
                &wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3, 2 => Float32x3],
                36,
                back,
                wgpu::CompareFunction::Less,
            ),
        }
    }
}

pub struct MeshPipeline<'a> {
    pub label: &'a str,
    pub module: &'a wgpu::ShaderModule,
    pub vertex_entry: &'a str,
    pub fragment_entry: &'a str,
    pub layouts: &'a [&'a wgpu::BindGroupLayout],
    pub attributes: &'a [wgpu::VertexAttribute],
    pub stride: u64,
    pub cull: Option<wgpu::Face>,
    pub format: wgpu::TextureFormat,
    pub blend: Option<wgpu::BlendState>,
    /// Depth test against [`DEPTH_FORMAT`] (depth written), if any.
    pub depth: Option<wgpu::CompareFunction>,
}

pub fn mesh_pipeline(device: &wgpu::Device, p: MeshPipeline<'_>) -> wgpu::RenderPipeline {
    let layout = gpu::pipeline_layout(device, p.label, p.layouts);
    device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some(p.label),
        layout: Some(&layout),
        vertex: wgpu::VertexState {
            module: p.module,
            entry_point: Some(p.vertex_entry),
            compilation_options: Default::default(),
            buffers: &[Some(wgpu::VertexBufferLayout {
                array_stride: p.stride,
                step_mode: wgpu::VertexStepMode::Vertex,
                attributes: p.attributes,
            })],
        },
        primitive: wgpu::PrimitiveState { cull_mode: p.cull, ..Default::default() },
        depth_stencil: p.depth.map(|compare| wgpu::DepthStencilState {
            format: DEPTH_FORMAT,
            depth_write_enabled: Some(true),
            depth_compare: Some(compare),
            stencil: Default::default(),
            bias: Default::default(),
        }),
        multisample: wgpu::MultisampleState::default(),
        fragment: Some(wgpu::FragmentState {
            module: p.module,
            entry_point: Some(p.fragment_entry),
            compilation_options: Default::default(),
            targets: &[Some(wgpu::ColorTargetState {
                format: p.format,
                blend: p.blend,
                write_mask: wgpu::ColorWrites::ALL,
            })],
        }),
        multiview_mask: None,
        cache: None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn overlapping_regions_are_drawn_last_with_both_objects() {
        let base = Features { caustics: true, ..Features::default() };
        let (sphere, duck) = (Features { sphere: true, ..base }, Features { duck: true, ..base });
        let both = Features { sphere: true, duck: true, ..base };
        let draws = with_overlaps(vec![([100, 100, 300, 250], sphere), ([250, 200, 500, 400], duck)]);
        println!("{draws:?}");
        assert_eq!(
            draws,
            vec![([100, 100, 200, 150], sphere), ([250, 200, 250, 200], duck), ([250, 200, 50, 50], both)]
        );
        let apart = with_overlaps(vec![([0, 0, 10, 10], sphere), ([20, 20, 30, 30], duck)]);
        assert_eq!(apart.len(), 2, "no overlap, no third draw");
    }
}
