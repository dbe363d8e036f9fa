//! What was drawn in the tank with the pointer, as text for a share link: walls and erasures
//! as polylines, and the ruler, in whole millimetres from the tray's middle. A wall drawn
//! through (−120, 40), (−120, 200) and a ruler from (−200, 0) to (200, 0) read
//! `W-120,40,-120,200_R-200,0,200,0` (only characters a URL keeps as they are, and commas).

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

/// The most items and points a sketch is read with (a longer one is cut, with a warning).
const MOST_POINTS: usize = 4000;

fn mm(v: f32) -> i32 {
    (v * 1e3).round() as i32
}

/// `strokes` and `ruler` as text; strokes that continue the last one join its polyline.
pub fn format(strokes: &[Stroke], ruler: Option<Ruler>) -> String {
    let mut items: Vec<(char, Vec<(f32, f32)>)> = Vec::new();
    for s in strokes {
        let letter = if s.kind == CellKind::Wall { 'W' } else { 'E' };
        match items.last_mut() {
            Some((l, points)) if *l == letter && points.last() == Some(&s.from) => points.push(s.to),
            _ => items.push((letter, vec![s.from, s.to])),
        }
    }
    if let Some((a, b)) = ruler {
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
    items.iter().map(item).collect::<Vec<_>>().join("_")
}

/// The strokes and the ruler in `text` (positions clamped to ±`half_width`, m), or why it
/// cannot be read.
pub fn parse(text: &str, half_width: f32) -> Result<(Vec<Stroke>, Option<Ruler>), String> {
    let (mut strokes, mut ruler) = (Vec::new(), None);
    let text = text.trim();
    if text.is_empty() {
        return Ok((strokes, ruler));
    }
    for item in text.split('_') {
        let mut chars = item.chars();
        let letter = chars.next().unwrap_or(' ');
        let numbers: Result<Vec<f32>, _> =
            chars.as_str().split(',').map(|n| n.trim().parse::<i32>().map(|v| v as f32)).collect();
        let numbers = numbers.map_err(|_| format!("\"{item}\" is not a letter and whole millimetres"))?;
        if numbers.len() < 4 || numbers.len() % 2 == 1 {
            return Err(format!("\"{item}\" needs pairs of numbers, at least two"));
        }
        let at = |k: usize| {
            let c = |v: f32| (v * 1e-3).clamp(-half_width, half_width);
            (c(numbers[2 * k]), c(numbers[2 * k + 1]))
        };
        let kind = match letter {
            'W' => CellKind::Wall,
            'E' => CellKind::Water,
            'R' if numbers.len() == 4 => {
                ruler = Some((at(0), at(1)));
                continue;
            }
            _ => return Err(format!("\"{item}\" is not a wall (W), an erasure (E) or a ruler (R, two points)")),
        };
        for k in 1..numbers.len() / 2 {
            strokes.push(Stroke { from: at(k - 1), to: at(k), kind });
        }
        if strokes.len() > MOST_POINTS {
            return Err(format!("more than {MOST_POINTS} strokes"));
        }
    }
    Ok((strokes, ruler))
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
        let ruler = Some(((-0.2, 0.0), (0.2, 0.0)));
        let text = format(&strokes, ruler);
        println!("{text}");
        assert_eq!(text, "W-120,40,-120,100,-120,200_E30,30,30,60_R-200,0,200,0");
        let (read, read_ruler) = parse(&text, 0.3).expect("a sketch");
        assert_eq!((read.len(), format(&read, read_ruler)), (strokes.len(), text));
        assert!(parse("W1,2,3", 0.3).is_err());
        assert!(parse("Q1,2,3,4", 0.3).is_err());
        assert_eq!(parse("R-900,0,900,0", 0.3).unwrap().1, Some(((-0.3, 0.0), (0.3, 0.0))));
    }
}
