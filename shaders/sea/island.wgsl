// The island in the open sea (sea/island.rs makes its heightmap). Its land is a grid over the
// map lifted to the ground's height, sand by the water, grass above, rock where it is steep,
// lit by the sun and the sky and seen through the haze. Under the water the sea reads the same
// map: light reaching the floor and coming back is dimmed by Beer-Lambert along its path
// (exp(-a L) per channel), so the shallows take the floor's colour, turning to the deep sea's
// own light with depth; where the water is shallowest it foams on the crests.

// Height (m), dh/dx, dh/dz of the ground, ISLAND_MAP_TEXELS a side over the map's square.
@group(2) @binding(3) var island_map: texture_2d<f32>;
// The land mirrored in the sea plane, at half the frame's size: sqrt(colour / MIRROR_RANGE),
// coverage in alpha.
@group(3) @binding(0) var mirror_map: texture_2d<f32>; // (binding 1: shaders/sea/foam.wgsl)


const SAND: vec3<f32> = vec3<f32>(0.50, 0.42, 0.28);
const WET_SAND: vec3<f32> = vec3<f32>(0.30, 0.24, 0.15);
const GRASS: vec3<f32> = vec3<f32>(0.09, 0.16, 0.04);
const ROCK: vec3<f32> = vec3<f32>(0.30, 0.28, 0.25);
const DRY_GRASS: vec3<f32> = vec3<f32>(0.20, 0.19, 0.07);
// The land's detail finer than its map (2.5 m a texel): the largest size of its noise (m),
// and how many octaves, each half the size before (the last 6 cm).
const LAND_DETAIL_SIZE: f32 = 16.0;
const LAND_DETAIL_OCTAVES: i32 = 9;

fn on_island_map(p: vec2<f32>) -> bool {
    return all(abs(p - ISLAND_CENTRE) < vec2<f32>(ISLAND_MAP_HALF_WIDTH));
}

// The ground's height and slopes at (x, z) on the map (on_island_map).
fn ground_at(p: vec2<f32>) -> vec3<f32> {
    let uv = (p - ISLAND_CENTRE) / (2.0 * ISLAND_MAP_HALF_WIDTH) + 0.5;
    return textureSampleLevel(island_map, clamp_sampler, uv, 0.0).xyz;
}

fn ground_normal(ground: vec3<f32>) -> vec3<f32> {
    return normalize(vec3<f32>(-ground.y, 1.0, -ground.z));
}

// Value noise over the ground at p (x, z; m) in octaves from LAND_DETAIL_SIZE down, each
// weighted 0.8 of the one before (a grain is seen beside the patches) and left out once the
// pixel's footprint (m) reaches half its size, so that no octave finer than a pixel sparkles
// (and far land costs a few): about -1..1.
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
    return sum;
}

// The land's albedo at point p (m) with slope `rise` (rise over run), footprint as
// land_detail's: wet sand at the water, then dry sand, grass, and rock on steep ground; the
// lines between them bent and each mottled by the detail the map is too coarse for (sand
// a little, grass with dry patches, rock more).
fn land_albedo(p: vec3<f32>, rise: f32, footprint: f32) -> vec3<f32> {
    let d = land_detail(p.xz, footprint, 0.0);
    let h = p.y + 0.8 * d;
    let sand = mix(WET_SAND, SAND, smoothstep(0.0, 0.6, h)) * (1.0 + 0.35 * d);
    let grass = mix(GRASS, DRY_GRASS, smoothstep(-0.2, 0.4, land_detail(p.xz, footprint, 20.0))) * (1.0 + 0.5 * d);
    let land = mix(sand, grass, smoothstep(BEACH_TOP - 0.5, BEACH_TOP + 0.5, h));
    let rock = ROCK * (1.0 + 0.6 * d);
    return mix(land, rock, smoothstep(ROCK_SLOPE - 0.2, ROCK_SLOPE + 0.2, rise + 0.2 * d));
}

// Sunlight and skylight on ground facing n (the sky's light by how much of the sky it sees).
fn light_on_ground(n: vec3<f32>) -> vec3<f32> {
    return sun_light() * max(dot(n, scene.sun.xyz), 0.0) + sky_light() * upward_share(n);
}

// Sunlight on the floor `depth` m under rest point p, focused by the waves (caustics, with the
// sun overhead): the point a refracted ray reaches moves by k grad h, k = depth (1 - 1/n), so
// the light is spread by det(I + k H), H the surface's Hessian: here the finest cascade's (the
// short waves that make a floor's caustics), from its slope `s` at p (in its frame) and its
// slopes a texel on, turned to the world as its carry gradient is, faded as the pixel's
// footprint (m) outgrows it; plus the clicks' ripples' where the shallows reach their patch.
fn shallows_caustics(p: vec2<f32>, s: vec2<f32>, depth: f32, footprint: f32) -> f32 {
    let c = CASCADES - 1;
    let tile = sea.cascades[c].z;
    let step = tile / f32(SEA_LATTICE);
    let local = to_cascade(c, p);
    let sx = (cascade_texel(sea_surface, c, local + vec2<f32>(step, 0.0), tile).yz - s) / step;
    let sz = (cascade_texel(sea_surface, c, local + vec2<f32>(0.0, step), tile).yz - s) / step;
    let local_hessian = vec4<f32>(0.0, 0.0, sx.x, sz.y);
    let cross = vec4<f32>(0.0, 0.0, 0.0, 0.5 * (sx.y + sz.x));
    var hessian = add_gradient(vec3<f32>(0.0), c, cascade_weight(c, footprint), local_hessian, cross);
    if ISLAND_AT_PATCH {
        hessian += ripples_hessian(p, footprint);
    }
    let k = depth * (1.0 - IOR_AIR / IOR_WATER);
    let spread = (1.0 + k * hessian.x) * (1.0 + k * hessian.z) - k * k * hessian.y * hessian.y;
    return min(1.0 / max(abs(spread), 0.05), SHALLOWS_CAUSTICS_PEAK);
}

// The caustics' brightest, against the floor's mean light.
const SHALLOWS_CAUSTICS_PEAK: f32 = 6.0;

// What the eye sees under the surface along unit v refracted by normal n where the water is
// `depth` m deep over `ground`: the floor lit by the sun (times `focus`, its caustics) and the
// sky, dimmed along the light's way down and the view's way back (absorbed and scattered out
// of the beam), and the deep water's light over the rest.
fn seen_through_water(v: vec3<f32>, n: vec3<f32>, depth: f32, ground: vec3<f32>, focus: f32) -> vec3<f32> {
    let down = refract(v, n, IOR_AIR / IOR_WATER);
    let path = depth / max(-down.y, 0.2) + depth / max(scene.sun.y, 0.2);
    let fade = 1.0 - smoothstep(0.6 * SEE_DEPTH, SEE_DEPTH, depth); // SEE_DEPTH: island.rs
    let through = exp(-(SEA_ABSORPTION + SEA_SCATTERING) * max(path, 0.0)) * fade;
    let g = ground_normal(ground);
    let light = sun_light() * max(dot(g, scene.sun.xyz), 0.0) * focus + sky_light() * upward_share(g);
    return mix(deep_water(), SAND * light, through);
}

// Foam along the shore where the water is `depth` deep: at the waterline, and out to
// SHORE_FOAM_DEPTH on the crests (`lift`: the wave's height over the crest's, about -1 to 1),
// so it moves with the waves, broken into patches by the short waves (`ripple`: the finest
// cascade's slope over its rms, about -2 to 2, already read for the pixel).
fn shore_foam(depth: f32, lift: f32, ripple: f32) -> f32 {
    if depth > SHORE_FOAM_DEPTH {
        return 0.0;
    }
    let shallow = 1.0 - max(depth, 0.0) / SHORE_FOAM_DEPTH;
    let patches = clamp(0.25 * ripple, -0.5, 0.5);
    return smoothstep(0.45, 0.8, shallow + 0.35 * lift + 0.5 * patches);
}

struct IslandOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) world: vec3<f32>,
}

// Vertex `index` of the land's grid over the map's square, LAND_GRID + 1 a row (the mesh's
// indices, island.rs land_indices, name the quads above the water).
fn land_vertex(index: u32) -> vec3<f32> {
    let g = vec2<f32>(f32(index % (LAND_GRID + 1u)), f32(index / (LAND_GRID + 1u))) / f32(LAND_GRID);
    let p = ISLAND_CENTRE + (g * 2.0 - 1.0) * ISLAND_MAP_HALF_WIDTH;
    return vec3<f32>(p.x, ground_at(p).x, p.y);
}

// The land's colour at a point of it, lit, before the haze; footprint: the pixel's on it (m).
fn land_colour(world: vec3<f32>, footprint: f32) -> vec3<f32> {
    let ground = ground_at(world.xz);
    return land_albedo(world, length(ground.yz), footprint) * light_on_ground(ground_normal(ground));
}

// The swash: how far (m, in height) above the waves at its place the sand is still covered by
// the shore's foam running up it, fading to none.
const SWASH_HEIGHT: f32 = 0.2;

// The land's colour at `world` (lit, before the haze) where the waves run up it: the shore's
// foam (if drawn) over the sand within SWASH_HEIGHT of the sea's surface there, so that where
// the sea's grid cuts into the land the foam on either side meets, not sand against a
// cut-out of foam along the land's quads. Only land that low pays for the waves' lookup.
fn with_swash(colour: vec3<f32>, world: vec3<f32>, footprint: f32) -> vec3<f32> {
    if (sea.foam.y <= 0.0 || world.y > sea.foam.z + SWASH_HEIGHT) {
        return colour;
    }
    var waves = 0.0; // the sea's height there: waves_at's, without the carry it also reads
    for (var c = 0; c < CASCADES; c++) {
        let surface = cascade_texel(sea_surface, c, to_cascade(c, world.xz), sea.cascades[c].z);
        waves += cascade_weight(c, footprint) * surface.x;
    }
    let above = world.y - waves;
    let cover = (1.0 - smoothstep(0.0, SWASH_HEIGHT, above)) * sea.foam.y;
    return mix(colour, WHITECAP_ALBEDO * light_on_foam(vec3<f32>(0.0, 1.0, 0.0)), cover);
}

// The pixel's footprint (m) on the land at `world`; call in uniform control flow.
fn land_footprint(world: vec3<f32>) -> f32 {
    return max(length(dpdx(world)), length(dpdy(world)));
}

@vertex
fn vs_island(@builtin(vertex_index) index: u32) -> IslandOut {
    var out: IslandOut;
    out.world = land_vertex(index);
    out.clip = scene.view_proj * vec4<f32>(out.world, 1.0);
    return out;
}

@fragment
fn fs_island(in: IslandOut) -> @location(0) vec4<f32> {
    let to_point = in.world - sea.eye.xyz;
    let dist = length(to_point);
    let footprint = land_footprint(in.world);
    let colour = with_swash(land_colour(in.world, footprint), in.world, footprint);
    return finish(through_air(colour, to_point / dist, dist));
}

// The land upside down under the sea plane, seen by the same camera: what a level sea mirrors.
@vertex
fn vs_island_mirrored(@builtin(vertex_index) index: u32) -> IslandOut {
    var out: IslandOut;
    out.world = land_vertex(index);
    out.clip = scene.view_proj * vec4<f32>(out.world * vec3<f32>(1.0, -1.0, 1.0), 1.0);
    return out;
}

// Only what stands above the water is mirrored; its light comes the whole way from the land
// through the haze (the eye's way to the land's mirror image).
@fragment
fn fs_island_mirrored(in: IslandOut) -> @location(0) vec4<f32> {
    let footprint = land_footprint(in.world);
    if in.world.y < 0.0 {
        discard;
    }
    let to_image = in.world * vec3<f32>(1.0, -1.0, 1.0) - sea.eye.xyz;
    let dist = length(to_image);
    let colour = through_haze(land_colour(in.world, footprint), to_image / dist, dist);
    return vec4<f32>(sqrt(colour / MIRROR_RANGE), 1.0);
}

// The mirrored land seen by the sea's pixel at `pixel` (px) with normal n, moved by the
// waves' slopes and blurred up and down the screen by `rough`, the rms slope of the waves too
// small to draw there (a mirrored ray spreads by about that angle; the far sea's image is
// smeared as a rough sea's is): its colour and coverage.
// The slope tilts the image across the screen and along the view (up the screen for a slope
// towards the eye). The mirror's texels are cleared to nothing, so a filtered texel is
// weighted by its coverage: its colour is taken back out of it before it is squared.
fn mirrored_land(pixel: vec2<f32>, n: vec3<f32>, rough: f32) -> vec4<f32> {
    let across = normalize(sea.right.xyz);
    let ahead = normalize(vec3<f32>(sea.forward.x, 0.0, sea.forward.z));
    let tilt = vec2<f32>(dot(n, across), dot(n, ahead));
    let centre = pixel * sea.mirror.xy + MIRROR_WOBBLE * tilt;
    let spread = vec2<f32>(0.0, MIRROR_BLUR * rough / length(sea.up.xyz));
    // Four taps over [-spread, spread], the inner two weighted twice: three, a spread apart,
    // left three copies of the land's outline, stepped, where the smear is wider than a pixel.
    let m = (textureSampleLevel(mirror_map, clamp_sampler, centre - spread, 0.0)
        + 2.0 * textureSampleLevel(mirror_map, clamp_sampler, centre - spread / 3.0, 0.0)
        + 2.0 * textureSampleLevel(mirror_map, clamp_sampler, centre + spread / 3.0, 0.0)
        + textureSampleLevel(mirror_map, clamp_sampler, centre + spread, 0.0)) / 6.0;
    let shade = m.rgb / max(m.a, 1.0e-3);
    return vec4<f32>(shade * shade * MIRROR_RANGE, m.a);
}
