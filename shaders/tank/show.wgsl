// The tank's picture, seen through the orbit camera: each pixel's ray meets the plane of the
// tray, where the chosen view is laid out at the tray's scale: the screen's image (shrunk by
// the lamp's magnification so it lies under the tray it comes from), the heights as colour
// (troughs dark blue, crests pale; barriers grey, glass plates green) or the intensity h^2.


// The tray plane's point under a pixel (x, z in m), or w 0 where the ray misses it.
fn on_plane(uv: vec2<f32>) -> vec3<f32> {
    let ndc = vec2<f32>(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0);
    let near = pic.inverse_view_proj * vec4<f32>(ndc, 0.0, 1.0);
    let far = pic.inverse_view_proj * vec4<f32>(ndc, 1.0, 1.0);
    let a = near.xyz / near.w;
    let b = far.xyz / far.w;
    if (a.y > 0.0) == (b.y > 0.0) {
        return vec3<f32>(0.0);
    }
    let p = mix(a, b, a.y / (a.y - b.y));
    return vec3<f32>(p.x, p.z, 1.0);
}

fn screen_colour(xz: vec2<f32>) -> vec3<f32> {
    let on_screen = xz * pic.screen.y;
    let uv = vec2<f32>(0.5 + on_screen.x / (2.0 * pic.screen.x), 0.5 - on_screen.y / (2.0 * pic.screen.x));
    if any(uv < vec2<f32>(0.0)) || any(uv > vec2<f32>(1.0)) {
        return BENCH;
    }
    return paper_at(uv);
}

fn cell_colour(xz: vec2<f32>) -> vec3<f32> {
    let w = pic.tray.x;
    if any(abs(xz) > vec2<f32>(w)) {
        // The tray's frame, then the bench.
        return select(BENCH, vec3<f32>(0.25, 0.22, 0.2), all(abs(xz) < vec2<f32>(w * FRAME_SHARE)));
    }
    let p = vec2<i32>((xz + w) / (2.0 * w) * pic.screen.z);
    let m = textureLoad(medium, p, 0);
    if m.w == WALL {
        return vec3<f32>(0.35);
    }
    let c = cell_of(p);
    var colour: vec3<f32>;
    if pic.view.x < 1.5 {
        let s = clamp(c.x / pic.view.y, -1.0, 1.0) * 0.5 + 0.5;
        colour = mix(vec3<f32>(0.0, 0.02, 0.12), vec3<f32>(0.75, 0.9, 1.0), s);
    } else {
        let s = clamp(sqrt(c.z) / pic.view.y, 0.0, 1.5);
        colour = vec3<f32>(s * 1.2, s * s * 0.8, s * s * s * 0.3);
    }
    // Beaches a little darker; plates tinted green.
    colour *= 1.0 - 0.35 * clamp(m.z / 400.0, 0.0, 1.0);
    return select(colour, mix(colour, vec3<f32>(0.2, 0.6, 0.35), 0.3), m.w == PLATE);
}

// Whether tray point xz lies on one of the slits' lines (drawn from between the slits on).
fn on_slit_line(xz: vec2<f32>) -> bool {
    let d = vec2<f32>(xz.x, xz.y - pic.lines.y);
    if d.y <= 0.0 || any(abs(xz) > vec2<f32>(pic.tray.x)) {
        return false;
    }
    for (var k = 0; k < i32(pic.lines.x); k++) {
        let a = pic.line_angles[k / 4][k % 4];
        if abs(d.x * cos(a) - d.y * sin(a)) < 0.5 * LINE_WIDTH {
            return true;
        }
    }
    return false;
}

@fragment
fn fs_show(in: FullscreenOut) -> @location(0) vec4<f32> {
    // The view's own part of the target (its right half beside the apparatus).
    let uv = vec2<f32>((in.uv.x - pic.halves.z) / pic.halves.w, in.uv.y);
    let hit = on_plane(uv);
    // A pixel's size in the picture (uv) and on the tray (m), for the instruments' lines.
    let pixel = abs(vec2<f32>(dpdx(uv.x), dpdy(uv.y)));
    let foot = max(length(fwidth(hit.xy)), 1e-5);
    var colour = BENCH;
    if hit.z > 0.0 && pic.view.x < 0.5 {
        colour = screen_colour(hit.xy);
    } else if hit.z > 0.0 {
        colour = cell_colour(hit.xy);
    }
    if hit.z > 0.0 && pic.lines.x > 0.0 && on_slit_line(hit.xy) {
        colour = vec3<f32>(0.9, 0.75, 0.1);
    }
    let on_tray = hit.z > 0.0 && all(abs(hit.xy) <= vec2<f32>(pic.tray.x));
    colour = with_instruments(colour, hit.xy, on_tray, uv, pixel, foot);
    if ENCODE_SRGB {
        colour = linear_to_srgb(colour);
    }
    return vec4<f32>(colour, 1.0);
}
