//! Named starting states for lessons: each is only parameter values (and optionally a camera),
//! so a share link is a preset too. Chosen by `preset=` in the URL, a `<wave-pool preset>`
//! attribute, `mount({ preset })` or the Preset select of the controls.

use crate::camera::OrbitCamera;
use crate::params::{table, Params};

/// A named set of parameter values (by the parameter table's names) and a camera to start from.
#[derive(Clone, Copy, Debug)]
pub struct Preset {
    /// What `preset=` takes.
    pub name: &'static str,
    pub label: &'static str,
    /// What a student sees, in a sentence.
    pub help: &'static str,
    /// Parameter values; the parameters not named keep their defaults.
    pub values: &'static [(&'static str, f32)],
    /// Camera yaw, pitch (degrees) and distance (m), or the default view.
    pub camera: Option<[f32; 3]>,
}

/// The bar's amplitude in the tank's lessons (mm): plane waves keep their height, so less than a
/// dipper's focuses the lamp's light near the screen.
const PLANE_WAVE_AMPLITUDE: f32 = 0.15;

pub const PRESETS: &[Preset] = &[
    Preset {
        name: "classic",
        label: "The classic look",
        help: "One sphere that stays where it is put (G drops it), reflecting walls, caustics: the pool as the classic WebGL Water shows it.",
        values: &[("objects", 1.0), ("gravity", 0.0), ("absorbing_walls", 0.0), ("caustics", 1.0), ("damping", 0.5)],
        camera: None,
    },
    Preset {
        name: "calm",
        label: "Calm water",
        help: "Nothing in the pool, small drops, waves that die out quickly at absorbing walls: a quiet surface to study one ripple at a time.",
        values: &[("objects", 0.0), ("damping", 2.0), ("absorbing_walls", 1.0), ("drop_strength", 0.006)],
        camera: Some([-25.0, 50.0, 3.6]),
    },
    Preset {
        name: "busy",
        label: "A busy pool",
        help: "The sphere and the duck floating on fast, lively water with big drops and reflecting walls.",
        values: &[
            ("objects", 3.0),
            ("gravity", 1.0),
            ("wave_speed", 0.9),
            ("damping", 0.1),
            ("drop_radius", 0.07),
            ("drop_strength", 0.03),
            ("absorbing_walls", 0.0),
        ],
        camera: None,
    },
    Preset {
        name: "fresnel",
        label: "Lesson: Fresnel reflectance",
        help: "Calm, empty water seen low across the pool, so the angle of incidence runs from about 50° near you to grazing at the far side: switch the Fresnel model and watch the reflection and the plot change.",
        values: &[
            ("objects", 0.0),
            ("fresnel", 0.0),
            ("damping", 1.0),
            ("drop_strength", 0.006),
            ("sun_elevation", 40.0),
            ("exposure", -0.4),
            // The cut-away box: from this low the deck's coping would hide the near water.
            ("setting", 1.0),
        ],
        camera: Some([-25.0, 14.0, 3.8]),
    },
    Preset {
        name: "glint",
        label: "Lesson: the sun's glint",
        help: "Looking towards a low sun: drag across the water to make waves and see Blinn-Phong's glint stretched along the view; switch the highlight to Phong and change the shininess to compare.",
        values: &[
            ("objects", 0.0),
            ("sun_azimuth", 0.0),
            ("sun_elevation", 30.0),
            ("exposure", -0.8),
            ("specular", 1.0),
            ("shininess", 3000.0),
            ("wave_speed", 0.8),
            ("damping", 0.2),
        ],
        camera: Some([180.0, 30.0, 3.2]),
    },
    Preset {
        name: "breeze",
        label: "Lesson: ambient waves",
        help: "A light breeze makes sharp-crested waves travel across the pool under your ripples; switch Ambient waves to modes to see the pool's own standing waves, which meet every wall flat, to gerstner for water moving in circles, or to fft for a spectrum of thousands of waves (the spectrum debug view shows each model's waves).",
        values: &[("objects", 2.0), ("ambient", 1.0), ("wind_speed", 3.0), ("wave_height", 0.012), ("wind_direction", 30.0)],
        camera: None,
    },
    Preset {
        name: "ocean",
        label: "Lesson: an FFT ocean",
        help: "Tessendorf's ocean in the pool: a Phillips spectrum of about a thousand waves on a 128-point lattice, summed by an FFT every frame; the debug view shows the spectrum, downwind of the wind's direction.",
        values: &[
            ("objects", 2.0),
            ("ambient", 4.0),
            ("fft_size", 128.0),
            ("wind_speed", 5.0),
            ("wave_height", 0.015),
            ("wave_spread", 60.0),
            ("debug_view", 6.0),
        ],
        camera: None,
    },
    Preset {
        name: "flat",
        label: "Lesson: flat water vs ray tracing",
        help: "The games' flat water (left) against the ray tracer (right), the sphere half out of the water: drag the divider across the sphere. Left, its submerged half sits unbent at its true depth and the reflections wobble by a fixed shift; right, the water lifts it and bends everything by the waves' slopes. Make ripples and switch the distortion to ripples to see the same waves with faked optics.",
        values: &[
            ("objects", 1.0),
            ("gravity", 1.0),
            ("render_mode", 2.0),
            ("split", 0.5),
            ("flat_distortion", 0.0),
        ],
        camera: Some([-25.0, 22.0, 3.8]),
    },
    Preset {
        name: "lake",
        label: "Lesson: water colour",
        help: "Green lake water: it absorbs red, green and blue faster than the pool's, and scatters a green-blue light of its own, so the deep end turns green instead of dark (turn the scattered light to 0 to see plain Beer-Lambert).",
        values: &[
            ("absorption_red", 1.6),
            ("absorption_green", 0.35),
            ("absorption_blue", 0.45),
            ("scatter_red", 0.02),
            ("scatter_green", 0.09),
            ("scatter_blue", 0.08),
            ("view_colour", 1.0),
        ],
        camera: None,
    },
    Preset {
        name: "noon",
        label: "Noon",
        help: "The sun almost overhead: a deep blue sky, short shadows, the brightest caustics on the floor.",
        values: &[("sun_elevation", 82.0), ("sun_azimuth", 30.0), ("exposure", 0.3)],
        camera: None,
    },
    Preset {
        name: "evening",
        label: "Evening",
        help: "A low warm sun from the side, the picture exposed for it: long shadows across the deck, the water dark where the rim shades it, the far wall lit by the sun's caustics.",
        values: &[("sun_elevation", 20.0), ("sun_azimuth", -90.0), ("exposure", 0.4)],
        camera: None,
    },
    Preset {
        name: "sea",
        label: "Lesson: the open sea",
        help: "Open water to the horizon in a moderate breeze: five FFT cascades of different tile sizes, so no pattern repeats; the grid the sea is drawn on is projected from the screen, so its detail follows your view; the haze takes sea and sky to one colour at the horizon (turn Fog off to see the sea's edge); the island ahead stands in turquoise shallows with foam along its shore and is mirrored in the water (turn on Show the grid to see the grid). Click near the middle to make ripples in the patch of simulated water and watch them run out; the rubber duck there, as much larger as the patch is than the pool, rides the waves and leaves a wake: drag it to see one.",
        values: &[("scene", 1.0), ("sun_elevation", 30.0), ("sun_azimuth", 0.0), ("exposure", -0.8)],
        camera: Some(crate::sea::DEFAULT_VIEW),
    },
    Preset {
        name: "shore",
        label: "Lesson: ripples in the shallows",
        help: "The island's beach by the patch of simulated water, in a light breeze under a high sun: the waves' slopes focus the sunlight into a net of caustics on the sand a few metres down. Click the water to make ripples: where the depth is right their rings focus into bright lines on the floor, which show them far better than the surface itself does. The duck's bobbing draws rings of its own, and its shadow lies on the sand.",
        values: &[
            ("scene", 1.0),
            ("sea_island", 2.0),
            ("sea_wind", 5.0),
            ("sea_wave_height", 0.4),
            ("sun_elevation", 55.0),
            ("sun_azimuth", 130.0),
        ],
        camera: Some([160.0, 35.0, 30.0]),
    },
    Preset {
        name: "dawn",
        label: "A calm sea at dawn",
        help: "A low sun ahead over a calm sea: its glint spread into a long path of glitter on the small waves, the sky warm along the horizon.",
        values: &[
            ("scene", 1.0),
            ("sun_elevation", 10.0),
            ("sun_azimuth", 0.0),
            ("sea_wind", 4.0),
            ("sea_wave_height", 0.3),
            ("sea_choppiness", 0.5),
            ("exposure", -1.7),
        ],
        camera: Some([180.0, 6.0, 30.0]),
    },
    Preset {
        name: "storm",
        label: "A storm at sea",
        help: "A strong wind raises 5 m waves with sharpened crests under a low sun, in thick haze; the duck is tossed among the whitecaps.",
        values: &[
            ("scene", 1.0),
            ("sea_wind", 20.0),
            ("sea_wave_height", 5.0),
            ("sea_choppiness", 1.5),
            ("sea_fog_distance", 1500.0),
            ("sun_elevation", 15.0),
            ("sun_azimuth", 60.0),
            ("exposure", -1.9),
        ],
        camera: Some([-30.0, 12.0, 80.0]),
    },
    Preset {
        name: "tank",
        label: "Ripple tank: one dipper",
        help: "A school ripple tank seen from above: a dipper bobs ten times a second in the middle of a tray of water 10 mm deep, and the lamp over the tank throws its rings onto the screen below as bright circles, because every crest focuses the light like a lens. Switch the view to the heights to see the waves themselves; change the frequency and watch the rings crowd together (the wavelength is the speed over the frequency).",
        values: &[("scene", 2.0), ("tank_setup", 0.0)],
        camera: Some(crate::tank::START_VIEW),
    },
    Preset {
        name: "single_slit",
        label: "Ripple tank: one slit",
        help: "A straight bar makes plane waves that meet a barrier with one gap. Past the gap they spread out in a fan; the narrower the gap against the wavelength, the wider the fan (try the slit width).",
        values: &[("scene", 2.0), ("tank_setup", 3.0), ("tank_amplitude", PLANE_WAVE_AMPLITUDE)],
        camera: Some(crate::tank::START_VIEW),
    },
    Preset {
        name: "double_slit",
        label: "Ripple tank: two slits",
        help: "Plane waves through two gaps 90 mm apart: the waves from the two gaps cross, and where crest meets crest the screen shows bright lines, while between them, where crest meets trough, the water stays still. The still lines fan out at angles where the paths differ by half a wavelength; switch the view to the intensity to see them.",
        values: &[("scene", 2.0), ("tank_setup", 4.0), ("tank_amplitude", PLANE_WAVE_AMPLITUDE)],
        camera: Some(crate::tank::START_VIEW),
    },
    Preset {
        name: "refraction",
        label: "Ripple tank: refraction",
        help: "Plane waves run onto a glass plate under the water. The water over it is shallower, so the waves slow down and come closer together, and where they cross the plate's slanting edge they bend: Snell's law for water waves.",
        values: &[("scene", 2.0), ("tank_setup", 5.0), ("tank_amplitude", PLANE_WAVE_AMPLITUDE)],
        camera: Some(crate::tank::START_VIEW),
    },
    Preset {
        name: "lens",
        label: "Ripple tank: a lens",
        help: "A lens-shaped glass plate under the water: the waves slow down over it, and the middle of each front spends longest over the plate, so the straight fronts come out curved and meet at a focus behind it, as light does behind a glass lens.",
        values: &[("scene", 2.0), ("tank_setup", 6.0), ("tank_amplitude", PLANE_WAVE_AMPLITUDE)],
        camera: Some(crate::tank::START_VIEW),
    },
    Preset {
        name: "doppler",
        label: "Ripple tank: a moving source",
        help: "A dipper moving across the tank at 0.12 m/s, about 40 % of the waves' speed: ahead of it the crests crowd together, behind it they spread out, as the pitch of a passing siren rises and falls. Raise its speed past the waves' (about 0.31 m/s) and it outruns its own waves: a bow wave.",
        values: &[("scene", 2.0), ("tank_setup", 7.0)],
        camera: Some(crate::tank::START_VIEW),
    },
    Preset {
        name: "reflection",
        label: "Ripple tank: a curved mirror",
        help: "Straight waves run into a curved wall shaped like a parabola. Each part of the wall sends them back at its own angle, and all of them meet at one point in front of it, the focus, as light does in a torch's mirror or a satellite dish. Switch the view to the intensity to see the bright focus.",
        values: &[("scene", 2.0), ("tank_setup", 8.0), ("tank_amplitude", PLANE_WAVE_AMPLITUDE)],
        camera: Some(crate::tank::START_VIEW),
    },
    Preset {
        name: "standing",
        label: "Ripple tank: standing waves",
        help: "Straight waves run into a straight wall and come back through themselves. Where they meet they add up to standing waves: lines of still water (nodes) half a wavelength apart, and between them water that goes up and down without going anywhere. Switch the view to the heights and turn the strobe to the dippers' frequency.",
        values: &[("scene", 2.0), ("tank_setup", 9.0), ("tank_amplitude", PLANE_WAVE_AMPLITUDE)],
        camera: Some(crate::tank::START_VIEW),
    },
    Preset {
        name: "phased_array",
        label: "Ripple tank: a phased array",
        help: "Four dippers in a row, 30 mm apart (a little over half a wavelength at 6 Hz), each a quarter of a cycle behind the one before. Their waves add up in one direction only, a beam turned about 25° towards the lagging end: change the phase step and the beam swings round without anything moving, as a phased-array radar or an ultrasound probe steers its beam. Switch the view to the intensity to see the beam.",
        values: &[
            ("scene", 2.0),
            ("tank_setup", 1.0),
            ("tank_dippers", 4.0),
            ("tank_slit_spacing", 30.0),
            ("tank_frequency", 6.0),
            ("tank_phase", 90.0),
        ],
        camera: Some(crate::tank::START_VIEW),
    },
];

impl Preset {
    /// Starts over from this preset: every parameter but the display's (resolution, frame
    /// budget) at its default, then the preset's values, and its view (or the default view).
    pub fn apply(&self, params: &mut Params, camera: &mut OrbitCamera) {
        for p in table().iter().filter(|p| p.group != "Display") {
            params.reset_at(p.index);
        }
        for &(name, value) in self.values {
            let _ = params.set_by_name(name, value);
        }
        let [yaw, pitch, distance] = self.camera.unwrap_or_else(|| {
            let view = OrbitCamera::default();
            [view.yaw, view.pitch, view.distance]
        });
        (camera.yaw, camera.pitch, camera.distance) = (yaw, pitch, distance);
    }
}

/// The preset called `name`.
pub fn find(name: &str) -> Option<&'static Preset> {
    PRESETS.iter().find(|p| p.name.eq_ignore_ascii_case(name))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params;

    #[test]
    fn every_preset_names_known_parameters_with_values_in_their_ranges() {
        for preset in PRESETS {
            for &(name, value) in preset.values {
                let spec = params::find(name).unwrap_or_else(|| panic!("{}: unknown parameter {name}", preset.name));
                assert_eq!(
                    spec.sanitise(value),
                    value,
                    "{}: {name} = {value} is outside its range or choices",
                    preset.name
                );
            }
            // Each scene's camera has its own limits.
            let scene = preset.values.iter().find(|(name, _)| *name == "scene").map_or(0.0, |&(_, v)| v);
            let limits = crate::scenes::camera_limits(scene.into());
            if let Some([_, pitch, distance]) = preset.camera {
                assert!((limits.pitch.0..=limits.pitch.1).contains(&pitch), "{}: pitch {pitch}", preset.name);
                assert!(
                    (limits.distance.0..=limits.distance.1).contains(&distance),
                    "{}: distance {distance}",
                    preset.name
                );
            }
            println!("{}: {} values", preset.name, preset.values.len());
        }
        assert!(find("CALM").is_some() && find("nothing").is_none());
    }

    /// The whitecaps' variant costs a sixth of lavapipe's shading: the sea of the `sea` and
    /// `shore` presets (the default's wind), which never folds far enough to show foam, must
    /// not take it; the storm's waves must.
    #[test]
    fn only_the_storms_sea_takes_the_whitecaps() {
        use crate::ambient::cascades::SeaWaves;
        for (name, expected) in [("sea", false), ("shore", false), ("storm", true)] {
            let (mut params, mut camera) = (Params::default(), OrbitCamera::default());
            find(name).unwrap().apply(&mut params, &mut camera);
            let waves = SeaWaves::new(&crate::scenes::sea::sea_settings(&params).waves(), crate::sea::SEA_LATTICE);
            let breaks = waves.may_break(&waves.layers(0.0));
            println!("{name}: may break {breaks}");
            assert_eq!(breaks, expected, "{name}");
        }
    }
}
