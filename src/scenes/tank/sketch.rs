//! What was drawn in the tank with the pointer, as text for a share link: walls and erasures
//! as polylines, the ruler, and the dippers moved (their number, then where), in whole
//! millimetres from the tray's middle. A wall drawn through (−120, 40), (−120, 200), a ruler
//! from (−200, 0) to (200, 0) and the first dipper moved to (50, −30) read
//! `W-120,40,-120,200_R-200,0,200,0_D0,50,-30` (only characters a URL keeps as they are, and
//! commas).

use crate::tank::medium::CellKind;

/// A stroke of the pointer's wall tool: a segment (m) painted a wall or open water.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stroke {
    pub from: (f32, f32),
    pub to: (f32, f32),
    pub kind: CellKind,
}

/// The ruler: from one end to the other (m).
pub type Ruler = ((f32, f32), (f32, f32));

/// What was drawn: strokes in order, the ruler, the dippers moved (index, place in m).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Sketch {
    pub strokes: Vec<Stroke>,
    pub ruler: Option<Ruler>,
    pub moved: Vec<(usize, (f32, f32))>,
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
    items.iter().map(item).chain(moved).collect::<Vec<_>>().join("_")
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
        let numbers: Result<Vec<f32>, _> =
            chars.as_str().split(',').map(|n| n.trim().parse::<i32>().map(|v| v as f32)).collect();
        let numbers = numbers.map_err(|_| format!("\"{item}\" is not a letter and whole millimetres"))?;
        let c = |v: f32| (v * 1e-3).clamp(-half_width, half_width);
        if letter == 'D' && numbers.len() == 3 && (0.0..crate::tank::MAX_DIPPERS as f32).contains(&numbers[0]) {
            sketch.moved.push((numbers[0] as usize, (c(numbers[1]), c(numbers[2]))));
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
                    "\"{item}\" is not a wall (W), an erasure (E), a ruler (R, two points) or a moved dipper (D, its number and place)"
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
        let sketch = Sketch { strokes, ruler: Some(((-0.2, 0.0), (0.2, 0.0))), moved: vec![(1, (0.05, -0.03))] };
        let text = format(&sketch);
        println!("{text}");
        assert_eq!(text, "W-120,40,-120,100,-120,200_E30,30,30,60_R-200,0,200,0_D1,50,-30");
        let read = parse(&text, 0.3).expect("a sketch");
        assert_eq!((read.strokes.len(), format(&read)), (sketch.strokes.len(), text));
        assert!(parse("W1,2,3", 0.3).is_err());
        assert!(parse("Q1,2,3,4", 0.3).is_err());
        assert!(parse("D9,1,2", 0.3).is_err());
        assert_eq!(parse("R-900,0,900,0", 0.3).unwrap().ruler, Some(((-0.3, 0.0), (0.3, 0.0))));
    }
}
