//! The choices fixed when the demo is created, and their specs (the one source of their
//! names, ranges and defaults for the web options, the URL and the command line).

use crate::params::ParamId;

/// Choices fixed when the demo is created.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DemoOptions {
    /// Simulation cells per side at the start (a power of two); the `sim_size` parameter
    /// starts at the nearest of its choices and changes it later.
    pub sim_size: u32,
    /// Caustics map texels per side.
    pub caustics_size: u32,
    /// Quads per side of the water surface mesh. Software rasterisers pay mostly per
    /// triangle, and the surface is shaded per pixel anyway: 48 costs little detail.
    pub surface_grid: u32,
    /// Whether the device can render into float textures. Without, the water is simulated
    /// by the CPU reference and the caustics map is 8-bit; the picture stays the same.
    pub float_targets: bool,
}

/// One creation option as the shells show it (web mount options and URL, CLI flags): its
/// name, range and default; any integer in the range is allowed.
#[derive(Clone, Copy, Debug)]
pub struct OptionSpec {
    pub name: &'static str,
    pub label: &'static str,
    pub min: u32,
    pub max: u32,
    pub default: u32,
}

impl OptionSpec {
    /// `value` clamped to the range.
    pub fn clamp(&self, value: u32) -> u32 {
        value.clamp(self.min, self.max)
    }
}

impl DemoOptions {
    /// The creation options' table: the one source of their names, ranges and defaults.
    pub const SPECS: [OptionSpec; 2] = [
        OptionSpec {
            name: "meshSize",
            label: "quads per side of the water surface mesh",
            min: 16,
            max: 512,
            default: 48,
        },
        OptionSpec {
            name: "causticsSize",
            label: "texels per side of the caustics map",
            min: 128,
            max: 2048,
            default: 512,
        },
    ];

    /// Options from raw values: the simulation size as the `sim_size` parameter would take it,
    /// mesh and caustics sizes clamped to their specs.
    pub fn clamped(sim_size: u32, surface_grid: u32, caustics_size: u32) -> Self {
        let [mesh, caustics] = &Self::SPECS;
        Self {
            sim_size: crate::params::spec(ParamId::SimSize).sanitise(sim_size as f32) as u32,
            surface_grid: mesh.clamp(surface_grid),
            caustics_size: caustics.clamp(caustics_size),
            float_targets: true,
        }
    }
}

/// The largest sizes a device is asked to draw and simulate with (cells, quads, texels per
/// side).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SizeCaps {
    pub sim_size: u32,
    pub surface_grid: u32,
    pub caustics_size: u32,
}

/// What a software rasteriser (no GPU: SwiftShader in a browser, llvmpipe) is given at most in
/// a page: twice the defaults per side. The largest options (1024 cells, 512 quads, 2048
/// texels) took 7.6 s a frame on SwiftShader beside a second browser, long enough for the
/// browser to give the page up; at these caps a frame takes under a second.
pub const SOFTWARE_CAPS: SizeCaps = SizeCaps { sim_size: 512, surface_grid: 128, caustics_size: 1024 };

impl DemoOptions {
    /// These options within `caps`, and what was reduced: (option name, asked, given).
    pub fn capped(self, caps: SizeCaps) -> (Self, Vec<(&'static str, u32, u32)>) {
        let [mesh, caustics] = &Self::SPECS;
        let sim_name = crate::params::spec(ParamId::SimSize).name;
        let mut reduced = Vec::new();
        let mut cap = |name, value: u32, most: u32| {
            if value > most {
                reduced.push((name, value, most));
            }
            value.min(most)
        };
        let options = Self {
            sim_size: cap(sim_name, self.sim_size, caps.sim_size),
            surface_grid: cap(mesh.name, self.surface_grid, caps.surface_grid),
            caustics_size: cap(caustics.name, self.caustics_size, caps.caustics_size),
            float_targets: self.float_targets,
        };
        (options, reduced)
    }
}

impl Default for DemoOptions {
    fn default() -> Self {
        let [mesh, caustics] = &Self::SPECS;
        Self {
            sim_size: crate::params::spec(ParamId::SimSize).default as u32,
            surface_grid: mesh.default,
            caustics_size: caustics.default,
            float_targets: true,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    pub(super) fn creation_options_clamp_and_snap_to_their_specs() {
        assert_eq!(
            DemoOptions::clamped(300, 4, 99_999),
            DemoOptions { sim_size: 256, surface_grid: 16, caustics_size: 2048, float_targets: true }
        );
        assert_eq!(DemoOptions::clamped(5000, 100, 700).sim_size, 1024);
        assert_eq!(DemoOptions::clamped(0, 100, 700).sim_size, 128);
        let d = DemoOptions::default();
        assert_eq!(DemoOptions::clamped(d.sim_size, d.surface_grid, d.caustics_size), d, "defaults lie in range");
    }

    #[test]
    fn software_caps_reduce_only_what_is_over_them_and_say_what() {
        let largest = DemoOptions::clamped(1024, 512, 2048);
        let (capped, reduced) = largest.capped(SOFTWARE_CAPS);
        println!("largest options on a software rasteriser: {capped:?}, reduced {reduced:?}");
        assert_eq!((capped.sim_size, capped.surface_grid, capped.caustics_size), (512, 128, 1024));
        assert_eq!(reduced, [("sim_size", 1024, 512), ("meshSize", 512, 128), ("causticsSize", 2048, 1024)]);
        let d = DemoOptions::default();
        assert_eq!(d.capped(SOFTWARE_CAPS), (d, vec![]), "the defaults fit a software rasteriser");
        // The caps are sizes the options can take.
        let c = DemoOptions::clamped(SOFTWARE_CAPS.sim_size, SOFTWARE_CAPS.surface_grid, SOFTWARE_CAPS.caustics_size);
        assert_eq!((c.sim_size, c.surface_grid, c.caustics_size), (512, 128, 1024));
    }
}
