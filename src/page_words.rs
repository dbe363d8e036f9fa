//! The words of the page and the viewer that are not in the parameter table (buttons, notices,
//! the Fresnel plot's axis), in English: the source of `locales/en.ftl`'s first section
//! (`wavepool messages` writes it), of the English page (`pageWords()`: no catalogue is fetched
//! for English) and of the viewer. An id with a dot is an attribute of the message before it
//! ("reset.title": the Reset button's tooltip). `{ $name }` is a value the page fills in.

pub const PAGE_WORDS: &[(&str, &str)] = &[
    ("language", "Language"),
    ("controls", "Controls"),
    ("preset", "Preset"),
    ("preset.title", "Start over from a lesson's settings and view"),
    ("preset-choose", "choose…"),
    ("preset-applied", "Preset { $name } applied."),
    ("preset-press-enter", "Press Enter to apply the preset { $name }."),
    ("reset", "Reset"),
    ("reset.title", "Back to how this page started: its parameters and view, calm water, the objects in place"),
    ("defaults", "Defaults"),
    ("defaults.title", "Set every parameter to its default"),
    ("share-link", "Share link"),
    ("share-link.title", "Copy a link that opens this pool with these parameters and this view"),
    ("embed-code", "Copy embed code"),
    ("embed-code.title", "Copy an <iframe> that shows this pool, as it is now, in another page"),
    ("link-copied", "Link copied."),
    ("embed-code-copied", "Embed code copied."),
    ("fullscreen", "Fullscreen"),
    ("fullscreen.title", "Fullscreen (Esc leaves it)"),
    ("play", "Play"),
    ("play.title", "Play: start the water and the objects moving"),
    ("pause", "Pause"),
    ("pause.title", "Pause: stop the water and the objects"),
    ("on", "on"),
    ("off", "off"),
    ("dipper", "Dipper { $number }"),
    (
        "notice-no-gpu",
        "This browser draws without a GPU, so the largest sizes are reduced to keep it responsive: { $sizes }.",
    ),
    ("notice-slow-resolution", "Frames took over a second here: the resolution is now automatic."),
    ("notice-slow-grid", "Frames took over a second here: the simulation grid is reduced to { $cells } cells."),
    ("fresnel-plot", "Reflectance against the angle of incidence: the chosen Fresnel model over the exact curve"),
    ("fresnel-angle", "angle of incidence"),
    (
        "fresnel-caption",
        "Reflectance: chosen model (blue) over exact (grey); from air solid, from under water dashed; | your view",
    ),
    ("status-loading", "Loading the water…"),
    ("status-device-lost", "The graphics device was lost; restarting…"),
    ("status-waiting", "Waiting for a free GPU context: scroll another water demo on this page out of view."),
    ("page-intro", "Click or drag on the water to make ripples, drag a floating object to move it, drag elsewhere to turn the camera; scroll or pinch to zoom. With the demo focused: space pauses, G drops the objects, L puts the sun behind you."),
    ("page-starting", "Starting the water…"),
    ("page-running", "Running on { $api }, { $adapter }."),
    ("page-running-unnamed", "Running on { $api } (the browser does not tell which GPU)."),
    ("page-failed", "The water could not start here: the box below says why."),
    ("costs-gpu", "GPU time drawing the water: { $times }."),
    ("costs-no-gpu-time", "GPU time: this browser does not measure it (no WebGPU timestamps)."),
    ("costs-between", "Between frames: { $times }."),
    ("note-flat-under-water", "Flat water is an above-water technique: under the water the ray tracer draws."),
    ("reading-probe-frequency", "Probe frequency"),
    ("reading-probe-swing", "Probe swing"),
    ("reading-ruler", "Ruler"),
    ("viewer-reset-water", "Reset water"),
    ("viewer-reset-water.title", "Flatten the water and put the sphere back"),
    ("viewer-frame", "frame: { $cpu } ms CPU, { $between } ms between frames"),
    ("viewer-gpu", "GPU: { $stages }"),
    ("viewer-gpu-none", "GPU time: this device has no timestamp queries"),
    ("viewer-gpu-waiting", "GPU time: waiting for the first timestamps"),
    ("viewer-costs", "drawing the water (caustics + shading): { $costs }"),
    ("viewer-water", "water: { $cells }² cells, { $seconds } s simulated"),
    ("viewer-adapter", "adapter: { $name }"),
    ("viewer-reset-one", "reset"),
    ("viewer-reset-one.title", "Reset to default"),
    ("error-backend-forced", "This page asked for { $api } only (backend={ $backend }), and this browser could not start it:"),
    ("error-backend-forced-fix", "Remove backend={ $backend } from the address or the options (or set backend=auto) to let the demo choose a backend this browser has."),
    ("error-no-backend", "This browser could not start the water demo: neither WebGPU nor WebGL2 worked (graphics acceleration may be turned off in its settings)."),
    ("error-no-webgpu", "WebGPU: this browser does not offer it (navigator.gpu is missing)"),
    ("error-stopped", "The water demo stopped: { $reason }"),
    ("error-device-lost", "The graphics device was lost and could not be restarted: { $reason }"),
    ("error-crashed", "The water demo crashed: { $reason }"),
    ("error-restart", "The water demo could not start again: { $reason }"),
    ("fallback-picture", "A still picture of the water pool (the live demo could not start here)"),
    ("canvas-label", "Water pool. Drag on the water to make ripples, drag the sphere to move it, drag elsewhere to turn the camera. Keys: arrows turn, + and - zoom, Enter makes a drop in the middle, space pauses, G gravity, L light."),
    ("embed-title", "Interactive water pool (wavepool)"),
    ("stage-simulation", "simulation"),
    ("stage-caustics", "caustics"),
    ("stage-maps", "maps"),
    ("stage-screen", "screen"),
    ("stage-shading", "shading"),
    ("stage-the-tank", "the tank"),
    ("stage-waves", "waves"),
];

/// The English text of `id` ("reset", or "reset.title" for an attribute).
pub fn english(id: &str) -> Option<&'static str> {
    PAGE_WORDS.iter().find(|(i, _)| *i == id).map(|&(_, text)| text)
}

/// The English text of `id` with its `{ $name }`s filled in from `args` ("" for an unknown id).
pub fn english_with(id: &str, args: &[(&str, String)]) -> String {
    let mut text = english(id).unwrap_or("").to_owned();
    for (name, value) in args {
        text = text.replace(&format!("{{ ${name} }}"), value);
    }
    text
}
