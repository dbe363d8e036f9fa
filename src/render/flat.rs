//! Flat water, the games' technique (seeds 000, 002, 003), drawn beside the ray tracer for
//! comparison. The scene is drawn twice more into textures: from the camera mirrored in the
//! water plane with everything under the plane clipped (the reflection), and from the camera
//! itself with everything above it clipped (the refraction, dimmed by the straight path
//! through the water). A flat plane at rest level then reads both at its own screen
//! position, shifted by a distortion (a scrolled dUdV map, or the simulation's slopes), and
//! blends them by Fresnel. Clipping is a discard behind a variant constant (`CLIP_SIDE`):
//! clip distances are optional in WebGPU and absent on WebGL2.

use glam::{Mat4, Vec4};

use super::render_mode::{Distortion, FlatCaustics, RenderMode};
use super::Features;
use crate::gpu;
use crate::param_spec::{slider, Control, ParamSpec};
use crate::sim::SplitMix64;

/// Texels per side of the dUdV map.
pub const DUDV_SIZE: u32 = 128;
/// Times the dUdV map repeats across the pool's width.
pub const DUDV_TILES: f32 = 3.0;
/// Surface slope the dUdV map's largest value stands for (its normals tilt up to atan of it).
pub const DUDV_SLOPE: f32 = 0.15;
/// Slope of the flat water's normal that shifts the textures by the whole `flat_strength`:
/// the dUdV map's largest, and for the `ripples` distortion a clear ripple's (the simulation's
/// ripples are gentler than the map's churn).
pub const REFERENCE_SLOPE: f32 = DUDV_SLOPE;
pub const RIPPLE_REFERENCE_SLOPE: f32 = 0.04;
/// Metres of water path that the refraction texture's alpha 1 stands for (the pool's longest
/// straight path is about 3 m).
pub const PATH_SCALE: f32 = 4.0;
/// Width (pixels) of the split view's divider line, and of the grip in its middle.
pub const DIVIDER_LINE: u32 = 2;
pub const DIVIDER_GRIP: (u32, u32) = (10, 48);

/// The flat-water settings of a frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FlatView {
    pub mode: RenderMode,
    /// The divider's place, a fraction of the width from the left (split mode).
    pub split: f32,
    pub distortion: Distortion,
    /// Largest shift of the texture lookups, a fraction of the screen.
    pub strength: f32,
    /// How far the dUdV map has scrolled (tiles, in [0, 1)).
    pub move_factor: f32,
    /// Size of the reflection and refraction textures against the scene's (0.25-1).
    pub resolution: f32,
    pub caustics: FlatCaustics,
    /// Water shallower than this along the view (m) is distorted less.
    pub soft_edge: f32,
    /// Height of the water plane (m): the rest level the floating bodies raise.
    pub plane: f32,
}

impl FlatView {
    /// The pixel column where the ray-traced part starts on a target `width` pixels wide
    /// (`width` when all of it is flat).
    pub fn divider(&self, width: u32) -> u32 {
        match self.mode {
            RenderMode::Split => ((self.split.clamp(0.0, 1.0) * width as f32).round() as u32).min(width),
            _ => width,
        }
    }

    /// The variant everything on the flat side is drawn with (its two textures and, in the
    /// frame, the plane and the solids seen past it): `base` with the pool lit by the flat
    /// water's own light (real, fake or no caustics) instead of the ray tracer's choice, so
    /// that what is seen directly under the water (through the cut-away side of the pool)
    /// matches what the refraction texture shows.
    pub fn lit_features(&self, base: Features) -> Features {
        Features {
            caustics: self.caustics == FlatCaustics::Real,
            flat_caustics: self.caustics == FlatCaustics::Fake,
            flat_distortion: self.distortion,
            ..base
        }
    }

    /// The `flat` uniform: plane height, strength, scroll, soft edge.
    pub fn uniform(&self) -> [f32; 4] {
        [self.plane, self.strength, self.move_factor, self.soft_edge]
    }
}

/// Reflection in the plane y = h: (x, y, z) -> (x, 2h - y, z). `view_proj * mirror(h)` is the
/// mirrored camera; it puts a point of the plane at the same pixel as the camera does, so the
/// water reads the reflection at its own screen position.
pub fn mirror(h: f32) -> Mat4 {
    Mat4::from_cols(Vec4::X, -Vec4::Y, Vec4::Z, Vec4::new(0.0, 2.0 * h, 0.0, 1.0))
}

/// The dUdV map: `size`² texels of a tiling height H(u, v) = Σ a sin(2π(m u + n v) + φ) of
/// 24 waves with whole numbers (m, n) of periods across the tile (so its edges meet and its
/// mean slope is 0), amplitudes falling as |k|^-1.5; red and green hold ∂H/∂u and ∂H/∂v
/// scaled to [0, 1] (0.5 is flat; the largest slope is 0 or 1), blue H likewise.
pub fn dudv_map(size: u32, seed: u64) -> Vec<[u8; 4]> {
    let mut rng = SplitMix64(seed);
    let mut waves = Vec::new();
    while waves.len() < 24 {
        let m = rng.range(-8.0, 9.0).floor();
        let n = rng.range(-8.0, 9.0).floor();
        let k = (m * m + n * n).sqrt();
        if !(2.0..=8.0).contains(&k) {
            continue;
        }
        waves.push((m, n, k.powf(-1.5), rng.range(0.0, std::f32::consts::TAU)));
    }
    let tau = std::f32::consts::TAU;
    let fields: Vec<[f32; 3]> = (0..size * size)
        .map(|i| {
            let (u, v) = ((i % size) as f32 / size as f32, (i / size) as f32 / size as f32);
            waves.iter().fold([0.0; 3], |acc, &(m, n, a, phase)| {
                let theta = tau * (m * u + n * v) + phase;
                let c = a * tau * theta.cos();
                [acc[0] + c * m, acc[1] + c * n, acc[2] + a * theta.sin()]
            })
        })
        .collect();
    let peak = |c: usize| fields.iter().map(|f| f[c].abs()).fold(1e-9f32, f32::max);
    let (slope, height) = (peak(0).max(peak(1)), peak(2));
    let byte = |v: f32, scale: f32| ((v / scale * 0.5 + 0.5) * 255.0).round().clamp(0.0, 255.0) as u8;
    fields.iter().map(|f| [byte(f[0], slope), byte(f[1], slope), byte(f[2], height), 255]).collect()
}

/// The dUdV map as a texture (RGBA8, linear, one level: it is read at level 0).
pub fn dudv_texture(device: &wgpu::Device, queue: &wgpu::Queue) -> wgpu::TextureView {
    let usage = wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST;
    let format = wgpu::TextureFormat::Rgba8Unorm;
    let texture = gpu::texture_2d(device, "dudv map", (DUDV_SIZE, DUDV_SIZE, 1), 1, format, usage);
    gpu::write_texture_2d(queue, &texture, 0, bytemuck::cast_slice(&dudv_map(DUDV_SIZE, 16)));
    texture.create_view(&Default::default())
}

/// WGSL constants of the flat water, for the scene's passes (`super::shaders::scene_prelude_in`).
pub fn wgsl_constants() -> String {
    format!(
        "const DUDV_TILES: f32 = {DUDV_TILES:?};\nconst DUDV_SLOPE: f32 = {DUDV_SLOPE:?};\n\
         const FLAT_REFERENCE_SLOPE: f32 = {REFERENCE_SLOPE:?};\nconst RIPPLE_REFERENCE_SLOPE: f32 = {RIPPLE_REFERENCE_SLOPE:?};\nconst FLAT_PATH_SCALE: f32 = {PATH_SCALE:?};\n\
         const FLAT_RIPPLES: u32 = {}u;\n",
        Distortion::Ripples as u32
    )
}

/// Flat water (the games' technique) and the split view. (The parameter table, `params::table`, lists them in this order.)
pub const PARAMS: &[ParamSpec] = &[
    ParamSpec {
        name: "render_mode",
        label: "Water rendering",
        group: "Flat water",
        unit: "",
        control: Control::Choice { values: RenderMode::VALUES, names: RenderMode::NAMES },
        default: 0.0,
        help: "How the water surface is drawn. raytraced: every pixel of the surface traces its reflected and refracted rays through the pool. flat: the technique games use: the scene is drawn twice more into textures, mirrored in the water plane (reflection) and clipped under it (refraction), and a flat plane blends the two by Fresnel, wobbled by a distortion instead of bent by the waves. It is an above-water technique: under water the ray tracer draws. split: flat on the left, ray-traced on the right of a divider you drag.",
    },
    ParamSpec {
        name: "split",
        label: "Divider",
        group: "Flat water",
        unit: "",
        control: slider(0.0, 1.0, 0.01),
        default: 0.5,
        help: "Where the divider stands, as a fraction of the width from the left: flat water to its left, ray-traced to its right. Drag the divider on the canvas to move it.",
    },
    ParamSpec {
        name: "flat_distortion",
        label: "Distortion",
        group: "Flat water",
        unit: "",
        control: Control::Choice { values: Distortion::VALUES, names: Distortion::NAMES },
        default: 0.0,
        help: "What wobbles the flat water's reflection and refraction: dudv, a tiling distortion map (a dUdV map) scrolled over time (clicks make no ripples in it), or ripples, the simulation's own slopes (the same waves as the ray tracer, with faked optics).",
    },
    ParamSpec {
        name: "flat_strength",
        label: "Distortion strength",
        group: "Flat water",
        unit: "",
        control: slider(0.0, 0.08, 0.002),
        default: 0.02,
        help: "How far the reflection and refraction textures are shifted by the distortion, as a fraction of the screen. It does not grow with the distance to what is seen, as real refraction does: a rim far above the water wobbles as much as the tiles under it.",
    },
    ParamSpec {
        name: "dudv_speed",
        label: "Distortion speed",
        group: "Flat water",
        unit: "1/s",
        control: slider(0.0, 0.2, 0.005),
        default: 0.03,
        help: "Tiles of the dudv map scrolled per simulated second (it stops when the water is paused); with the dudv distortion.",
    },
    ParamSpec {
        name: "flat_resolution",
        label: "Texture resolution",
        group: "Flat water",
        unit: "",
        control: Control::Choice { values: &[0.25, 0.5, 0.75, 1.0], names: &["25%", "50%", "75%", "100%"] },
        default: 0.5,
        help: "Size of the reflection and refraction textures against the scene's: smaller is cheaper and blurrier.",
    },
    ParamSpec {
        name: "flat_caustics",
        label: "Caustics",
        group: "Flat water",
        unit: "",
        control: Control::Choice { values: FlatCaustics::VALUES, names: FlatCaustics::NAMES },
        default: 1.0,
        help: "Light on the pool under flat water: off (a calm surface's), fake (a highlight where the distortion's normal would send the sun straight down; no focusing, no pass) or real (the ray tracer's caustics map, one more pass).",
    },
    ParamSpec {
        name: "flat_soft_edge",
        label: "Soft edge",
        group: "Flat water",
        unit: "m",
        control: slider(0.0, 0.3, 0.01),
        default: 0.1,
        help: "Water shallower than this (along the view) is distorted less, hiding the seam where the flat plane meets the walls; 0 shows the seam.",
    },
];

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;

    #[test]
    fn the_mirrored_camera_puts_points_of_the_plane_where_the_camera_does() {
        let h = 0.013;
        let vp = Mat4::perspective_rh(0.8, 4.0 / 3.0, 0.01, 100.0)
            * Mat4::look_at_rh(Vec3::new(1.0, 2.0, 3.0), Vec3::ZERO, Vec3::Y);
        let mirrored = vp * mirror(h);
        let mut worst = 0.0f32;
        for p in [Vec3::new(0.3, h, -0.2), Vec3::new(-0.9, h, 0.7), Vec3::new(0.0, h, 0.0)] {
            let (a, b) = (vp * p.extend(1.0), mirrored * p.extend(1.0));
            worst = worst.max((a - b).abs().max_element());
        }
        let q = mirror(h).transform_point3(Vec3::new(0.2, 0.5, -0.1));
        println!("plane points' clip coordinates differ by {worst:e}; (0.2, 0.5, -0.1) -> {q}");
        assert!(worst < 1e-6);
        assert!((q - Vec3::new(0.2, 2.0 * h - 0.5, -0.1)).length() < 1e-6);
    }

    #[test]
    fn the_dudv_map_tiles_and_does_not_drift() {
        let size = 64;
        let map = dudv_map(size, 16);
        let at = |x: u32, y: u32| map[((y % size) * size + x % size) as usize];
        let diff = |a: [u8; 4], b: [u8; 4]| (0..3).map(|c| (a[c] as i32 - b[c] as i32).abs()).max().unwrap();
        let (mut seam, mut inside) = (0, 0);
        for i in 0..size {
            seam = seam.max(diff(at(size - 1, i), at(0, i))).max(diff(at(i, size - 1), at(i, 0)));
            for j in 0..size - 1 {
                inside = inside.max(diff(at(j, i), at(j + 1, i))).max(diff(at(i, j), at(i, j + 1)));
            }
        }
        let mean = |c: usize| map.iter().map(|t| t[c] as f32 / 255.0 - 0.5).sum::<f32>() / map.len() as f32;
        println!("largest step across the seam {seam}, inside {inside}; mean slopes {:.4}, {:.4}", mean(0), mean(1));
        assert!(seam <= inside, "the map does not tile");
        assert!(mean(0).abs() < 2.0 / 255.0 && mean(1).abs() < 2.0 / 255.0, "the map drifts");
        assert!(map.iter().any(|t| t[0] == 0 || t[0] == 255), "the slopes use the full range");
    }
}

/// GPU time of drawing the water (the caustics and shading stages) per render mode, smoothed
/// over recent frames and kept after switching away, so the panel can set the modes' costs
/// side by side.
#[derive(Clone, Debug, Default)]
pub struct ModeCosts {
    /// Milliseconds per [`RenderMode`] (ray-traced, flat, split), once measured.
    ms: [Option<f64>; 3],
}

impl ModeCosts {
    /// Takes a frame's stage times ([`StageTimer::latest`]) drawn in `mode`.
    pub fn observe(&mut self, mode: RenderMode, stages: [f64; 4]) {
        let drawing = stages[2] + stages[3];
        let slot = &mut self.ms[mode as usize];
        *slot = Some(slot.map_or(drawing, |old| 0.9 * old + 0.1 * drawing));
    }

    /// The smoothed milliseconds of `mode`, if it was drawn.
    pub fn of(&self, mode: RenderMode) -> Option<f64> {
        self.ms[mode as usize]
    }

    /// Each mode's cost, named by `name` (the viewer's words for the `render_mode` choices).
    pub fn summary_named(&self, name: impl Fn(RenderMode) -> String) -> String {
        [RenderMode::RayTraced, RenderMode::Flat, RenderMode::Split]
            .iter()
            .map(|&mode| (mode, name(mode)))
            .map(|(mode, name)| match self.of(mode) {
                Some(ms) => format!("{name} {ms:.1} ms"),
                None => format!("{name} –"),
            })
            .collect::<Vec<_>>()
            .join(" · ")
    }
}
