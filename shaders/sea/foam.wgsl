// The whitecaps: where the choppy crests fold they cover the water with foam, kept over time
// in a map (scenes/sea/render/foam.rs), drawn as a lace of bubbles anchored to the water.
// The map holds the foam's cover (0-1) in red over the sea plane round the origin,
// WHITECAP_MAP_TEXELS a side over WHITECAP_MAP_HALF_WIDTH each way, indexed by rest point
// (where the eye's ray meets the mean plane). Each frame a texel keeps its cover times
// sea.foam.w (e^(-steps dt / lifetime): the same fade at every frame rate) or takes the cover
// the crests make there now, whichever is more, so a broken crest leaves a fading trail.

@group(3) @binding(1) var whitecap_map: texture_2d<f32>;

// The kept foam's cover at rest point p, faded out over the map's outer tenth (past it the sea
// shows the foam of the moment only).
fn kept_whitecaps(p: vec2<f32>) -> f32 {
    let uv = p / (2.0 * WHITECAP_MAP_HALF_WIDTH) + 0.5;
    let from_middle = 2.0 * max(abs(uv.x - 0.5), abs(uv.y - 0.5));
    let fade = 1.0 - smoothstep(0.9, 1.0, from_middle);
    return textureSampleLevel(whitecap_map, clamp_sampler, uv, 0.0).r * fade;
}

// Foam's bubbles at p (in cells of about a unit): 1 on the walls between the cells, falling to
// 0 in the middle of the largest (Worley's distance to the second-nearest scattered point less
// that to the nearest).
fn foam_cells(p: vec2<f32>) -> f32 {
    let cell = floor(p);
    var nearest = vec2<f32>(8.0);
    for (var k = 0; k < 9; k++) {
        let c = cell + vec2<f32>(f32(k % 3 - 1), f32(k / 3 - 1));
        let d = distance(p, c + vec2<f32>(hash31(vec3<f32>(c, 1.7)), hash31(vec3<f32>(c, 9.1))));
        nearest = select(vec2<f32>(nearest.x, min(nearest.y, d)), vec2<f32>(d, nearest.x), d < nearest.x);
    }
    return 1.0 - clamp((nearest.y - nearest.x) * 1.6, 0.0, 1.0);
}

// How white the water is at rest point p (m) under foam of cover `cover`, seen at a footprint
// of `footprint` m. Thick foam is solid; as it thins, holes open in it where its lace is
// thinnest (bubbles of two sizes, FOAM_CELL and three times it, in patches of a few metres),
// so that its edge and its fading trail break into lace rather than a cut-out shape or a grey
// smear. Each size of the lace fades to its mean as a pixel's footprint grows to about half
// of it, so the far foam shows as white patches, neither sparkling nor grey.
const FOAM_CELL: f32 = 0.5;
const FOAM_CELLS_MEAN: f32 = 0.58; // foam_cells' mean over the plane
fn foam_lace(cover: f32, p: vec2<f32>, footprint: f32) -> f32 {
    if cover <= 0.0 {
        return 0.0;
    }
    let q = p / FOAM_CELL;
    let seen = footprint / FOAM_CELL; // the pixel's footprint in cells
    // Each size computed only while a pixel can show it (the others at their means).
    var bubbles = FOAM_CELLS_MEAN;
    var grain = 0.5;
    if seen < 0.7 {
        let swirl = vec2<f32>(value_noise_2d(q * 0.4, 1.0), value_noise_2d(q * 0.4, 7.0)) - 0.5;
        bubbles = mix(foam_cells(q + 1.5 * swirl), FOAM_CELLS_MEAN, smoothstep(0.15, 0.7, seen));
        grain = mix(value_noise_2d(q * 1.7, 2.0), 0.5, smoothstep(0.1, 0.4, seen));
    }
    var large = FOAM_CELLS_MEAN;
    if seen < 2.0 {
        large = mix(foam_cells(q / 3.0 + 17.0), FOAM_CELLS_MEAN, smoothstep(0.5, 2.0, seen));
    }
    let patches = value_noise_2d(q / 6.0, 3.7);
    let lace = 0.35 * bubbles + 0.2 * grain + 0.25 * large + 0.2 * patches;
    let threshold = 1.0 - cover;
    let soft = 0.05 + 0.6 * min(seen, 1.0);
    return smoothstep(threshold - soft, threshold + soft, lace);
}

// The light falling on foam facing n: the sky's over the half of it facing up, and the sun's
// (on a level sea, light_on_sea), so that it is shaded with the wave it lies on.
fn light_on_foam(n: vec3<f32>) -> vec3<f32> {
    return sky_light() * (0.5 + 0.5 * n.y) + sun_light() * max(dot(n, scene.sun.xyz), 0.0);
}

// A texel of the next map from the current one.
@fragment
fn fs_whitecaps(in: FullscreenOut) -> @location(0) vec4<f32> {
    let p = (in.uv - 0.5) * 2.0 * WHITECAP_MAP_HALF_WIDTH;
    let texel = 2.0 * WHITECAP_MAP_HALF_WIDTH / f32(WHITECAP_MAP_TEXELS);
    let kept = textureSampleLevel(whitecap_map, clamp_sampler, in.uv, 0.0).r * sea.foam.w;
    let now = whitecap_cover(squeezed(waves_at(p, texel).breaking_gradient));
    return vec4<f32>(max(kept, now), 0.0, 0.0, 1.0);
}
