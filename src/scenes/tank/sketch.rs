//! What was drawn in the tank with the pointer, as text for a share link: walls and erasures
//! as polylines, the ruler, and the dippers moved (their number from 0, then where), in
//! whole millimetres from the tray's middle, and the bar moved (its z); and the dippers given
//! settings of their own (their number, then frequency in Hz, amplitude in mm and phase in
//! degrees). A wall drawn through (−120, 40), (−120, 200), a ruler from (−200, 0) to (200, 0),
//! the first dipper moved to (50, −30), the bar to z = −150 and the second dipper set to
//! 12.5 Hz, 0.3 mm and −90° read
//! `W-120,40,-120,200_R-200,0,200,0_D0,50,-30_B-150_T1,12.5,0.3,-90` (only characters a URL
//! keeps as they are, and commas).

use crate::tank::medium::CellKind;
use crate::tank::tuning::Tuning;

/// A stroke of the pointer's wall tool: a segment (m) painted a wall or open water.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stroke {
    pub from: (f32, f32),
    pub to: (f32, f32),
    pub kind: CellKind,
}

/// The ruler: from one end to the other (m).
pub type Ruler = ((f32, f32), (f32, f32));

/// What was drawn: strokes in order, the ruler, the dippers moved (index, place in m), the
/// bar moved (its z, m) and the dippers with settings of their own (index, settings).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Sketch {
    pub strokes: Vec<Stroke>,
    pub ruler: Option<Ruler>,
    pub moved: Vec<(usize, (f32, f32))>,
    pub bar: Option<f32>,
    pub tuned: Vec<(usize, Tuning)>,
}

/// The most items and points a sketch is read with (a longer one is cut, with a warning).
const MOST_POINTS: usize = 4000;

fn mm(v: f32) -> i32 {
    (v * 1e3).round() as i32
}

/// `sketch` as text; strokes that continue the last one join its polyline.
pub fn format(sketch: &Sketch) -> String {
    let mut items: Vec<(char, Vec<(f32, f32)>)> = Vec::new();
    for s in &sketch.strokes {
        let letter = if s.kind == CellKind::Wall { 'W' } else { 'E' };
        match items.last_mut() {
            Some((l, points)) if *l == letter && points.last() == Some(&s.from) => points.push(s.to),
            _ => items.push((letter, vec![s.from, s.to])),
        }
    }
    if let Some((a, b)) = sketch.ruler {
        items.push(('R', vec![a, b]));
    }
    let item = |(letter, points): &(char, Vec<(f32, f32)>)| {
        let mut at: Vec<(i32, i32)> = points.iter().map(|&(x, z)| (mm(x), mm(z))).collect();
        // A press paints a dot before the drag goes on: the same point twice in a row.
        at.dedup();
        if at.len() == 1 {
            at.push(at[0]);
        }
        let numbers: Vec<String> = at.iter().flat_map(|(x, z)| [x.to_string(), z.to_string()]).collect();
        format!("{letter}{}", numbers.join(","))
    };
    let moved = sketch.moved.iter().map(|(k, (x, z))| format!("D{k},{},{}", mm(*x), mm(*z)));
    // To a hundredth of a hertz and of a millimetre, whole degrees (the sliders' steps).
    let short = |v: f32, scale: f32| ((v * scale).round() / scale).to_string();
    let tuned = sketch.tuned.iter().map(|(k, t)| {
        let (f, a, p) = (short(t.frequency, 100.0), short(t.amplitude * 1e3, 100.0), short(t.phase.to_degrees(), 1.0));
        format!("T{k},{f},{a},{p}")
    });
    let bar = sketch.bar.map(|z| format!("B{}", mm(z)));
    items.iter().map(item).chain(moved).chain(bar).chain(tuned).collect::<Vec<_>>().join("_")
}

/// What `text` says was drawn (positions clamped to ±`half_width`, m), or why it cannot be
/// read.
pub fn parse(text: &str, half_width: f32) -> Result<Sketch, String> {
    let mut sketch = Sketch::default();
    let text = text.trim();
    if text.is_empty() {
        return Ok(sketch);
    }
    for item in text.split('_') {
        let mut chars = item.chars();
        let letter = chars.next().unwrap_or(' ');
        let numbers: Result<Vec<f32>, _> = chars.as_str().split(',').map(|n| n.trim().parse::<f32>()).collect();
        let numbers = numbers
            .ok()
            .filter(|n| n.iter().all(|v| v.is_finite()))
            .ok_or_else(|| format!("\"{item}\" is not a letter and numbers"))?;
        let c = |v: f32| (v.round() * 1e-3).clamp(-half_width, half_width);
        let dipper = (0.0..crate::tank::MAX_DIPPERS as f32).contains(&numbers[0]) && numbers[0].fract() == 0.0;
        if letter == 'D' && numbers.len() == 3 && dipper {
            sketch.moved.push((numbers[0] as usize, (c(numbers[1]), c(numbers[2]))));
            continue;
        }
        if letter == 'B' && numbers.len() == 1 {
            sketch.bar = Some(c(numbers[0]));
            continue;
        }
        if letter == 'T' && numbers.len() == 4 && dipper {
            let own = Tuning { frequency: numbers[1], amplitude: numbers[2] * 1e-3, phase: numbers[3].to_radians() };
            // Each setting clamped to its range.
            let own = [("frequency", numbers[1]), ("amplitude", numbers[2]), ("phase", numbers[3])]
                .into_iter()
                .try_fold(own, |t, (name, v)| t.with(name, v))
                .expect("the tuning's own names");
            sketch.tuned.push((numbers[0] as usize, own));
            continue;
        }
        if numbers.len() < 4 || numbers.len() % 2 == 1 {
            return Err(format!("\"{item}\" needs pairs of numbers, at least two"));
        }
        let at = |k: usize| (c(numbers[2 * k]), c(numbers[2 * k + 1]));
        let kind = match letter {
            'W' => CellKind::Wall,
            'E' => CellKind::Water,
            'R' if numbers.len() == 4 => {
                sketch.ruler = Some((at(0), at(1)));
                continue;
            }
            _ => {
                return Err(format!(
                    "\"{item}\" is not a wall (W), an erasure (E), a ruler (R, two points), a moved dipper (D, its number and place), the moved bar (B, its z) or a dipper's own settings (T, its number, frequency, amplitude and phase)"
                ))
            }
        };
        for k in 1..numbers.len() / 2 {
            sketch.strokes.push(Stroke { from: at(k - 1), to: at(k), kind });
        }
        if sketch.strokes.len() > MOST_POINTS {
            return Err(format!("more than {MOST_POINTS} strokes"));
        }
    }
    Ok(sketch)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_sketch_reads_back_as_it_was_drawn() {
        let wall = |a, b| Stroke { from: a, to: b, kind: CellKind::Wall };
        let strokes = vec![
            wall((-0.12, 0.04), (-0.12, 0.1)),
            wall((-0.12, 0.1), (-0.12, 0.2)),
            Stroke { from: (0.03, 0.03), to: (0.03, 0.06), kind: CellKind::Water },
        ];
        let own = Tuning { frequency: 12.5, amplitude: 0.3e-3, phase: -std::f32::consts::FRAC_PI_2 };
        let (ruler, moved, tuned) = (Some(((-0.2, 0.0), (0.2, 0.0))), vec![(1, (0.05, -0.03))], vec![(1, own)]);
        let sketch = Sketch { strokes, ruler, moved, bar: Some(-0.15), tuned };
        let text = format(&sketch);
        println!("{text}");
        assert_eq!(text, "W-120,40,-120,100,-120,200_E30,30,30,60_R-200,0,200,0_D1,50,-30_B-150_T1,12.5,0.3,-90");
        let read = parse(&text, 0.3).expect("a sketch");
        assert_eq!((read.strokes.len(), format(&read)), (sketch.strokes.len(), text));
        assert!(parse("W1,2,3", 0.3).is_err());
        assert!(parse("Q1,2,3,4", 0.3).is_err());
        assert!(parse("D9,1,2", 0.3).is_err());
        assert!(parse("T1,NaN,1,2", 0.3).is_err());
        assert_eq!(parse("T0,99,-1,720", 0.3).unwrap().tuned[0].1.frequency, 25.0);
        assert_eq!(parse("R-900,0,900,0", 0.3).unwrap().ruler, Some(((-0.3, 0.0), (0.3, 0.0))));
    }
}
