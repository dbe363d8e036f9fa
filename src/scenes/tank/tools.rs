//! The pointer's tools that change the tray: a straight wall drawn from the press, and a dipper
//! or the bar carried by the move tool.

use super::{Stroke, TankScene};
use crate::tank::medium::CellKind;

/// How near a dipper or the bar (m) a press must be to pick it up with the move tool.
const PICK_DIPPER: f32 = 0.02;

/// What the move tool holds: a dipper (its index) or the bar.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Grab {
    Dipper(usize),
    Bar,
}

impl TankScene {
    /// The walls tool at `to` (m): a press starts a straight wall, the drag moves its far end
    /// (the cells are painted again, without the wall's last place).
    pub(super) fn draw_wall(&mut self, to: (f32, f32), continues: bool) {
        match self.strokes.last_mut() {
            Some(wall) if continues && wall.kind == CellKind::Wall => {
                wall.to = to;
                self.rebuild_due = true;
            }
            _ => {
                self.strokes.push(Stroke { from: to, to, kind: CellKind::Wall });
                self.medium.stroke(to, to, CellKind::Wall);
                self.medium_changed = true;
            }
        }
    }

    /// The move tool at `to` (m): a press picks up the nearest dipper, or the bar, within
    /// reach; the drag carries it (the bar along z, in the open water between the beaches).
    pub(super) fn move_source(&mut self, to: (f32, f32), continues: bool) {
        if !continues {
            let distance = |d: &crate::tank::medium::Dipper| (d.x - to.0).hypot(d.z - to.1);
            let dippers = (self.medium.sources.dippers.iter().enumerate()).map(|(k, d)| (Grab::Dipper(k), distance(d)));
            let bar = (self.medium.sources.bar.iter())
                .filter(|b| to.0.abs() <= b.half_length)
                .map(|b| (Grab::Bar, (b.z - to.1).abs()));
            self.moving = (dippers.chain(bar))
                .filter(|&(_, r)| r <= PICK_DIPPER)
                .min_by(|a, b| a.1.total_cmp(&b.1))
                .map(|(grab, _)| grab);
        }
        match self.moving {
            Some(Grab::Dipper(k)) => {
                self.picked = k;
                self.moved.retain(|&(j, _)| j != k);
                self.moved.push((k, to));
            }
            Some(Grab::Bar) => {
                let open = self.settings.half_width() - crate::tank::BEACH_SHARE * self.settings.size;
                self.bar_at = Some(to.1.clamp(-open, open));
            }
            None => return,
        }
        self.place_dippers();
    }
}
