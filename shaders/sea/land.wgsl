// The island's land as the eye sees it (drawn by island.wgsl's passes): sand by the water,
// grass above, rock where it is steep, from the map's height and slope; the detail the map is
// too coarse for (its texels 2 ISLAND_MAP_HALF_WIDTH / ISLAND_MAP_TEXELS apart, 2.5 m) as value
// noise filtered to the pixel; and where the waves run up it, the shore's foam (the swash).

const SAND: vec3<f32> = vec3<f32>(0.50, 0.42, 0.28);
const WET_SAND: vec3<f32> = vec3<f32>(0.30, 0.24, 0.15);
const GRASS: vec3<f32> = vec3<f32>(0.09, 0.16, 0.04);
const DRY_GRASS: vec3<f32> = vec3<f32>(0.20, 0.19, 0.07);
const ROCK: vec3<f32> = vec3<f32>(0.30, 0.28, 0.25);

// The land's detail: the largest size of its noise (m) and how many octaves, each half the
// size of the one before (the last 6 cm).
const LAND_DETAIL_SIZE: f32 = 16.0;
const LAND_DETAIL_OCTAVES: i32 = 9;
// The grass's dry patches: one octave of noise this size (m), its seed clear of land_detail's
// (0 to OCTAVES - 1). (A second land_detail cost SwiftShader's WebGPU a fifth of the shore's
// frame: it runs a loop's whole body for every pixel.)
const GRASS_PATCH_SIZE: f32 = 6.0;
const GRASS_PATCH_SEED: f32 = 20.0;

// Value noise over the ground at p (x, z; m) in octaves from LAND_DETAIL_SIZE down, each
// weighted 0.8 of the one before (a grain is seen beside the patches) and left out once the
// pixel's footprint (m) reaches half its size, so that no octave finer than a pixel aliases
// (and far land runs a few). Clamped to -1..1 (its spread is about ±0.3).
fn land_detail(p: vec2<f32>, footprint: f32, seed: f32) -> f32 {
    var sum = 0.0;
    var q = p;
    var size = LAND_DETAIL_SIZE;
    var weight = 0.45;
    for (var i = 0; i < LAND_DETAIL_OCTAVES; i++) {
        let fade = 1.0 - smoothstep(0.25 * size, 0.5 * size, footprint);
        if (fade <= 0.0) {
            break;
        }
        // Each octave turned (0.6, 0.8: about 53°) from the one before, so that their
        // lattices do not line up into a grid.
        q = vec2<f32>(0.6 * q.x - 0.8 * q.y, 0.8 * q.x + 0.6 * q.y);
        sum += weight * fade * (2.0 * value_noise_2d(q / size, seed + f32(i)) - 1.0);
        size *= 0.5;
        weight *= 0.8;
    }
    return clamp(sum, -1.0, 1.0);
}

// The land's albedo at point p (m) with slope `rise` (rise over run), footprint as
// land_detail's: wet sand at the water, then dry sand, grass, and rock on steep ground. The
// detail d bends the lines between them (the height by up to 0.8 m, the slope by 0.2) and
// mottles each: sand by ±35 %, grass by ±50 % with dry patches, rock by ±60 %.
fn land_albedo(p: vec3<f32>, rise: f32, footprint: f32) -> vec3<f32> {
    let d = land_detail(p.xz, footprint, 0.0);
    let h = p.y + 0.8 * d;
    let sand = mix(WET_SAND, SAND, smoothstep(0.0, 0.6, h)) * (1.0 + 0.35 * d);
    let dry = smoothstep(0.4, 0.7, value_noise_2d(p.xz / GRASS_PATCH_SIZE, GRASS_PATCH_SEED));
    let grass = mix(GRASS, DRY_GRASS, dry) * (1.0 + 0.5 * d);
    let land = mix(sand, grass, smoothstep(BEACH_TOP - 0.5, BEACH_TOP + 0.5, h));
    let rock = ROCK * (1.0 + 0.6 * d);
    return mix(land, rock, smoothstep(ROCK_SLOPE - 0.2, ROCK_SLOPE + 0.2, rise + 0.2 * d));
}

// Sunlight and skylight on ground facing n (the sky's light by how much of the sky it sees).
fn light_on_ground(n: vec3<f32>) -> vec3<f32> {
    return sun_light() * max(dot(n, scene.sun.xyz), 0.0) + sky_light() * upward_share(n);
}

// The land's colour at a point of it, lit, before the haze; footprint: the pixel's on it (m).
fn land_colour(world: vec3<f32>, footprint: f32) -> vec3<f32> {
    let ground = ground_at(world.xz);
    return land_albedo(world, length(ground.yz), footprint) * light_on_ground(ground_normal(ground));
}

// The pixel's footprint (m) on the land at `world`; call in uniform control flow.
fn land_footprint(world: vec3<f32>) -> f32 {
    return max(length(dpdx(world)), length(dpdy(world)));
}

// The swash: how far (m, in height) above the waves at its place the land is still covered by
// the shore's foam running up it, fading to none.
const SWASH_HEIGHT: f32 = 0.2;

// The land's colour at `world` (lit, before the haze) where the waves run up it: with the
// shore's foam drawn, land within SWASH_HEIGHT of the sea's height over the same rest point
// takes the foam's colour, as much as the sea's own foam at its waterline (shore_foam at depth
// 0, its patches left out), so that where the sea's grid cuts into the land's quads the foam
// on either side meets, not sand against a cut-out of foam. The waves' sideways carry (tens
// of centimetres) and the clicks' ripples are left out. Only land below the highest crest
// (sea.foam.z) and SWASH_HEIGHT reads the waves.
fn with_swash(colour: vec3<f32>, world: vec3<f32>, footprint: f32) -> vec3<f32> {
    if (sea.foam.y <= 0.0 || world.y > sea.foam.z + SWASH_HEIGHT) {
        return colour;
    }
    let waves = waves_height(world.xz, footprint);
    let at_waterline = shore_foam(0.0, waves / max(sea.foam.z, 0.1), 0.0);
    let cover = (1.0 - smoothstep(0.0, SWASH_HEIGHT, world.y - waves)) * at_waterline;
    return mix(colour, WHITECAP_ALBEDO * light_on_foam(vec3<f32>(0.0, 1.0, 0.0)), cover);
}
