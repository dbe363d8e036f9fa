// The lab's instruments drawn over the tank's picture: the probe's ring and the graph of its
// height over the last seconds in the picture's corner, the intensity graph over its line
// across the tray (time-averaged h^2 along it, the highest value a fixed height), and the
// ruler with a tick every centimetre. Each gives a colour and its coverage (alpha); `foot`
// is a pixel's size on the tray (m), so lines stay about a pixel wide at any zoom.

@group(0) @binding(3) var probe_ring: texture_2d<f32>;

const INK: vec3<f32> = vec3<f32>(1.0, 0.82, 0.2);
const GRAPH_INK: vec3<f32> = vec3<f32>(1.0, 0.4, 0.25);
// The trace panel's corners in the picture (uv, y down) and how high the graph over the
// intensity line rises (a share of the tray's half width).
const PANEL_MIN: vec2<f32> = vec2<f32>(0.6, 0.74);
const PANEL_MAX: vec2<f32> = vec2<f32>(0.97, 0.97);
const GRAPH_RISE: f32 = 0.3;
const RULER_WIDTH: f32 = 0.012;

// Coverage of a line of half width `half` (in the units of `d`) at distance `d`.
fn line(d: f32, half: f32, foot: f32) -> f32 {
    return clamp((half + 0.5 * foot - abs(d)) / foot, 0.0, 1.0);
}

fn probe_mark(xz: vec2<f32>, foot: f32) -> vec4<f32> {
    let r = length(xz - pic.probe.xy);
    return vec4<f32>(INK, line(r - 0.006, max(0.0008, 0.75 * foot), foot));
}

// The probe's sample at `age` fixed steps before the newest, in units of the graph's half
// height, or 2 (off the graph) where none was taken.
fn probe_sample(age: i32) -> f32 {
    let n = i32(pic.trace.z);
    if age < 0 || age >= i32(pic.trace.y) {
        return 2.0;
    }
    let h = textureLoad(probe_ring, vec2<i32>((i32(pic.trace.x) - age + n) % n, 0), 0).x;
    return clamp(h / pic.probe.w, -1.2, 1.2);
}

// The probe's graph: time from the left (the oldest sample kept) to now at the right.
fn trace_panel(uv: vec2<f32>, pixel: vec2<f32>) -> vec4<f32> {
    let q = (uv - PANEL_MIN) / (PANEL_MAX - PANEL_MIN);
    if any(q < vec2<f32>(0.0)) || any(q > vec2<f32>(1.0)) {
        return vec4<f32>(0.0);
    }
    let px = pixel / (PANEL_MAX - PANEL_MIN); // a pixel in panel units
    let n = pic.trace.z;
    // The samples this column spans (ages, newest 0), and the range of heights they cover.
    let age_right = (1.0 - q.x) * (n - 1.0);
    let age_span = px.x * (n - 1.0);
    var low = 2.0;
    var high = -2.0;
    let first = i32(floor(age_right - 0.5 * age_span));
    for (var a = first; a <= min(first + 8, i32(ceil(age_right + 0.5 * age_span))); a++) {
        let v = probe_sample(a);
        if v < 1.5 {
            low = min(low, v);
            high = max(high, v);
        }
    }
    // Heights up, the middle line at rest, a faint tick each second.
    let y = 0.5 - 0.45 * vec2<f32>(high, low);
    var colour = vec3<f32>(0.02, 0.03, 0.05);
    let seconds = age_right * pic.trace.w;
    colour += 0.08 * line(seconds - round(seconds), 0.0, px.x * (n - 1.0) * pic.trace.w);
    colour += 0.1 * line(q.y - 0.5, 0.0, px.y);
    let on_trace = high >= low && q.y >= y.x - px.y && q.y <= y.y + px.y;
    colour = select(colour, INK, on_trace);
    let frame = max(line(q.x, 0.0, px.x) + line(q.x - 1.0, 0.0, px.x), line(q.y, 0.0, px.y) + line(q.y - 1.0, 0.0, px.y));
    return vec4<f32>(mix(colour, vec3<f32>(0.5), min(frame, 1.0)), 0.85);
}

// The intensity at x (m) along the graph's line, interpolated between its cells, over the
// line's peak.
fn graph_value(x: f32) -> f32 {
    let cell = (x + pic.tray.x) / (2.0 * pic.tray.x) * pic.screen.z - 0.5;
    let j = i32((pic.graph.x + pic.tray.x) / (2.0 * pic.tray.x) * pic.screen.z);
    let i = i32(floor(cell));
    let a = cell_of(vec2<i32>(i, j)).z;
    let b = cell_of(vec2<i32>(i + 1, j)).z;
    return mix(a, b, fract(cell)) / max(pic.graph.z, 1e-12);
}

// The intensity graph: its line dashed across the tray, the curve over it towards +z.
fn graph_mark(xz: vec2<f32>, foot: f32) -> vec4<f32> {
    if abs(xz.x) > pic.tray.x {
        return vec4<f32>(0.0);
    }
    let rise = GRAPH_RISE * pic.tray.x;
    let dash = step(0.5, fract(xz.x / 0.01));
    let on_line = 0.6 * dash * line(xz.y - pic.graph.x, 0.0005, foot);
    let a = pic.graph.x + rise * graph_value(xz.x - foot);
    let b = pic.graph.x + rise * graph_value(xz.x + foot);
    let on_curve = line(xz.y - 0.5 * (a + b), 0.5 * abs(a - b) + max(0.0008, 0.5 * foot), foot);
    return select(vec4<f32>(vec3<f32>(0.9), on_line), vec4<f32>(GRAPH_INK, on_curve), on_curve > 0.0);
}

// The ruler: a strip on the left of the line from its start to its end, marked each 10 mm
// (longer each 50 and 100 mm).
fn ruler_mark(xz: vec2<f32>, foot: f32) -> vec4<f32> {
    let d = pic.ruler.zw - pic.ruler.xy;
    let span = length(d);
    if span < 0.001 {
        return vec4<f32>(0.0);
    }
    let along_dir = d / span;
    let p = xz - pic.ruler.xy;
    let along = dot(p, along_dir);
    let across = along_dir.x * p.y - along_dir.y * p.x;
    if along < -foot || along > span + foot || across < -foot || across > RULER_WIDTH {
        return vec4<f32>(0.0);
    }
    let cm = along / 0.01;
    let tick_len = select(select(0.3, 0.55, abs(cm / 5.0 - round(cm / 5.0)) < 0.01), 0.8, abs(cm / 10.0 - round(cm / 10.0)) < 0.01);
    let tick = line(along - round(cm) * 0.01, 0.0003, foot) * step(across, tick_len * RULER_WIDTH);
    let edge = line(across, 0.0003, foot);
    let ink = max(tick, edge);
    return vec4<f32>(mix(vec3<f32>(0.93, 0.86, 0.62), vec3<f32>(0.1), ink), 0.9);
}

// `colour` with the instruments that are in drawn over it.
fn with_instruments(colour: vec3<f32>, xz: vec2<f32>, on_tray: bool, uv: vec2<f32>, pixel: vec2<f32>, foot: f32) -> vec3<f32> {
    var c = colour;
    if on_tray && pic.graph.y > 0.0 {
        let g = graph_mark(xz, foot);
        c = mix(c, g.rgb, g.a);
    }
    if on_tray && pic.graph.w > 0.0 {
        let r = ruler_mark(xz, foot);
        c = mix(c, r.rgb, r.a);
    }
    if pic.probe.z > 0.0 {
        if on_tray {
            let m = probe_mark(xz, foot);
            c = mix(c, m.rgb, m.a);
        }
        let t = trace_panel(uv, pixel);
        c = mix(c, t.rgb, t.a);
    }
    return c;
}
