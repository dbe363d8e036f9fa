// The island in the open sea (sea/island.rs makes its heightmap). Its land is a grid over the
// map lifted to the ground's height, coloured as land.wgsl says, seen through the haze. Under
// the water the sea reads the same map: light reaching the floor and coming back is dimmed by
// Beer-Lambert along its path (exp(-a L) per channel), so the shallows take the floor's
// colour, turning to the deep sea's own light with depth; where the water is shallowest it
// foams on the crests.

// Height (m), dh/dx, dh/dz of the ground, ISLAND_MAP_TEXELS a side over the map's square.
@group(2) @binding(3) var island_map: texture_2d<f32>;
// The land mirrored in the sea plane, at half the frame's size: sqrt(colour / MIRROR_RANGE),
// coverage in alpha.
@group(3) @binding(0) var mirror_map: texture_2d<f32>; // (binding 1: shaders/sea/foam.wgsl)


// The land's colours and its detail are shaders/sea/land.wgsl's (SAND also lights the floor
// seen through the shallows here).

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

// The finest of the land's detail (m of footprint, land_detail) the mirror pass draws.
const MIRROR_DETAIL: f32 = 2.0;

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
    // The mirror is read blurred, at half size: its land's detail no finer than MIRROR_DETAIL.
    let colour = through_haze(land_colour(in.world, max(footprint, MIRROR_DETAIL)), to_image / dist, dist);
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
