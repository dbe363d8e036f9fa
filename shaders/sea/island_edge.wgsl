// The island's outline and its mirror image's, blended (scenes/sea/render/island.rs
// draws them).

// The land's outline without stair-steps: the land's mesh drawn again after the sky (and into
// the mirror after the land), grown outwards by ISLAND_EDGE_PUSH pixels, each pixel of it
// blended by the share of the pixel the land covers: along the pixel's ray, the least height
// it passes over ground standing out of the sea, across the ray, over the pixel's size there: a
// pixel whose middle lies on the outline half covered, one whose middle lies half a pixel out
// not at all (the pixels inside are the land's own mesh's).
// How far the grown mesh reaches out, in the frame's pixels (a texel of the half-size mirror).
const ISLAND_EDGE_PUSH: f32 = 2.0;
// The ray is searched ISLAND_EDGE_WINDOW of the land grid's cells either side of where the
// grown mesh's fragment lies on it (its outline's point grown, before the push back), in
// ISLAND_EDGE_STEPS steps, then round the lowest of them in ISLAND_EDGE_REFINE. (Searched
// across the whole map in 40 and 8 steps, the sea's frame took 12 ms more on lavapipe; 2.5
// cells either side in 10 missed the ridge in a third of the outline's columns at 320x240.)
const ISLAND_EDGE_WINDOW: f32 = 4.0;
// The factor the grown mesh's distance from the eye is pushed back by. (What lies behind the
// outline nearer than that hides its fringe: seen from high above, the sea behind a low
// outline.)
const ISLAND_EDGE_BEHIND: f32 = 1.5;
const ISLAND_EDGE_STEPS: i32 = 12;
const ISLAND_EDGE_REFINE: i32 = 6;

// The height (m) of the frame's pixel per metre along a ray.
fn pixel_angle() -> f32 {
    return 2.0 * length(sea.up.xyz) * sea.mirror.y;
}

// The side (m) of the land grid's cells.
fn land_cell() -> f32 {
    return 2.0 * ISLAND_MAP_HALF_WIDTH / f32(LAND_GRID);
}

// Vertex `index` of the grown land; `flip` -1 for its mirror image under the sea plane: moved
// across the eye's ray by ISLAND_EDGE_PUSH pixels, along the part of the ground's normal
// across it, then pushed back along its new ray to half as far again. On the screen it is the
// land grown by that much; in depth it lies behind the land and the sea in front of it, which
// hide all of it but the fringe round the land's outline (where the growth pushes the
// triangles' edges out past it, over the sky or what lies far behind).
fn land_edge_vertex(index: u32, flip: f32) -> vec3<f32> {
    let seen = vec3<f32>(1.0, flip, 1.0);
    let p = land_vertex(index) * seen;
    let n = ground_normal(ground_at(p.xz)) * seen;
    let ray = normalize(p - sea.eye.xyz);
    let across = n - ray * dot(n, ray);
    let by = ISLAND_EDGE_PUSH * pixel_angle() * distance(p, sea.eye.xyz);
    let grown = p + across / max(length(across), 1.0e-4) * by;
    return sea.eye.xyz + (grown - sea.eye.xyz) * ISLAND_EDGE_BEHIND;
}

// The height (m) of the land's mesh at (x, z) on the map: its grid's corners' ground, between
// them as its two triangles a quad lie (the diagonal from (i + 1, j) to (i, j + 1), island.rs
// land_indices): the outline the fringe continues is the mesh's (read from the texture, which
// rises above the mesh between its corners, the fringe's pixels against 4x4 supersampling
// differed by 5.3 on average, 4.5 from the mesh; 5.6 with no fringe).
fn land_mesh_height(p: vec2<f32>) -> f32 {
    let q = ((p - ISLAND_CENTRE) / (2.0 * ISLAND_MAP_HALF_WIDTH) + 0.5) * f32(LAND_GRID);
    let cell = clamp(floor(q), vec2<f32>(0.0), vec2<f32>(f32(LAND_GRID) - 1.0));
    let f = q - cell;
    let corner = ISLAND_CENTRE + (cell / f32(LAND_GRID) * 2.0 - 1.0) * ISLAND_MAP_HALF_WIDTH;
    let step = land_cell();
    let h10 = ground_at(corner + vec2<f32>(step, 0.0)).x;
    let h01 = ground_at(corner + vec2<f32>(0.0, step)).x;
    if f.x + f.y <= 1.0 {
        let h00 = ground_at(corner).x;
        return h00 + f.x * (h10 - h00) + f.y * (h01 - h00);
    }
    let h11 = ground_at(corner + vec2<f32>(step)).x;
    return h11 + (1.0 - f.x) * (h01 - h11) + (1.0 - f.y) * (h10 - h11);
}

// How near (m, up) the ray from `origin` along unit `dir` comes to the land standing out of
// the sea (negative: it goes into it) while above the sea, near `around` (m along it), and
// where (x: the height, y: t).
fn land_clearance(origin: vec3<f32>, dir: vec3<f32>, around: f32) -> vec2<f32> {
    let lo = ISLAND_CENTRE - vec2<f32>(ISLAND_MAP_HALF_WIDTH);
    let hi = ISLAND_CENTRE + vec2<f32>(ISLAND_MAP_HALF_WIDTH);
    let inv = 1.0 / select(dir.xz, vec2<f32>(1.0e-6), abs(dir.xz) < vec2<f32>(1.0e-6));
    let a = (lo - origin.xz) * inv;
    let b = (hi - origin.xz) * inv;
    var t0 = max(max(min(a.x, b.x), min(a.y, b.y)), 0.0);
    var t1 = min(max(a.x, b.x), max(a.y, b.y));
    // Only where the ray is above the sea: under it the sea hides the land, or mirrors none.
    let to_sea = -origin.y / select(dir.y, select(-1.0e-6, 1.0e-6, dir.y > 0.0), abs(dir.y) < 1.0e-6);
    t0 = select(t0, max(t0, to_sea), dir.y > 0.0);
    t1 = select(t1, min(t1, to_sea), dir.y < 0.0);
    let window = ISLAND_EDGE_WINDOW * land_cell() / max(length(dir.xz), 0.1);
    var best = vec2<f32>(1.0e9, around);
    var step = 2.0 * window / f32(ISLAND_EDGE_STEPS);
    var start = around - window;
    for (var pass_index = 0; pass_index < 2; pass_index++) {
        let count = select(ISLAND_EDGE_REFINE, ISLAND_EDGE_STEPS, pass_index == 0);
        for (var i = 0; i <= count; i++) {
            let t = start + step * f32(i);
            let p = origin + dir * t;
            let ground = land_mesh_height(p.xz);
            let clearance = select(1.0e9, p.y - ground, ground > 0.0 && t >= t0 && t <= t1);
            best = select(best, vec2<f32>(clearance, t), clearance < best.x);
        }
        start = best.y - step;
        step = 2.0 * step / f32(ISLAND_EDGE_REFINE);
    }
    return best;
}

// The share of the pixel (ray from origin along dir; `pixel` its height per metre along it)
// the land covers, and the land's point nearest it.
fn land_edge(origin: vec3<f32>, dir: vec3<f32>, pixel: f32, around: f32) -> vec4<f32> {
    let near = land_clearance(origin, dir, around);
    let p = origin + dir * near.y;
    // A ray into the land is the land's own mesh's to draw (here it passes under a ridge behind
    // the outline): only the outside half of the ramp is drawn. (The whole ramp outside, from
    // all at the outline, fattened the outline by half a pixel and raised spikes on the ridge:
    // its pixels' difference from 4x4 supersampling 5.6 -> 9.9 on average, against 5.3.)
    // The height over the land, across the ray.
    let gap = near.x * length(dir.xz);
    let cover = select(clamp(0.5 - gap / max(pixel * near.y, 1.0e-3), 0.0, 0.5), 0.0, near.x < 0.0);
    return vec4<f32>(p.x, land_mesh_height(p.xz), p.z, cover);
}

@vertex
fn vs_island_edge(@builtin(vertex_index) index: u32) -> IslandOut {
    var out: IslandOut;
    out.world = land_edge_vertex(index, 1.0);
    out.clip = scene.view_proj * vec4<f32>(out.world, 1.0);
    return out;
}

@fragment
fn fs_island_edge(in: IslandOut) -> @location(0) vec4<f32> {
    let dir = normalize(in.world - sea.eye.xyz);
    let edge = land_edge(sea.eye.xyz, dir, pixel_angle(), distance(in.world, sea.eye.xyz) / ISLAND_EDGE_BEHIND);
    let dist = distance(edge.xyz, sea.eye.xyz);
    // The pixel's footprint along the ground, as the land's own pixels take it at the outline.
    let facing = abs(dot(dir, ground_normal(ground_at(edge.xz))));
    let footprint = pixel_angle() * dist / max(facing, 0.1);
    let colour = with_swash(land_colour(edge.xyz, footprint), edge.xyz, footprint);
    var out = finish(through_air(colour, dir, dist));
    out.a = edge.w;
    return out;
}

// The same into the mirror: the ray from the eye to the image, mirrored in the sea plane, is
// the ray from the eye's mirror image up to the land (its texels premultiplied by coverage).
@vertex
fn vs_island_edge_mirrored(@builtin(vertex_index) index: u32) -> IslandOut {
    var out: IslandOut;
    out.world = land_edge_vertex(index, -1.0);
    out.clip = scene.view_proj * vec4<f32>(out.world, 1.0);
    return out;
}

@fragment
fn fs_island_edge_mirrored(in: IslandOut) -> @location(0) vec4<f32> {
    let flip = vec3<f32>(1.0, -1.0, 1.0);
    let to_grown = (in.world - sea.eye.xyz) / ISLAND_EDGE_BEHIND;
    // The land's mesh reaches under the sea, where nothing is mirrored and the mirror pass has
    // no sea to hide the grown mesh behind.
    if -(sea.eye.y + to_grown.y) < 0.0 {
        return vec4<f32>(0.0);
    }
    let dir = normalize(to_grown);
    let edge = land_edge(sea.eye.xyz * flip, dir * flip, MIRROR_SCALE * pixel_angle(), length(to_grown));
    let dist = distance(edge.xyz * flip, sea.eye.xyz);
    let colour = through_haze(land_colour(edge.xyz, max(pixel_angle() * dist, MIRROR_DETAIL)), dir, dist);
    return vec4<f32>(sqrt(colour / MIRROR_RANGE), 1.0) * edge.w;
}
