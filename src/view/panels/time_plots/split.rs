//! Over log |e|: the error split into the flexible pair's share and the rest ([`crate::analysis::swing`]):
//! at every sampling instant the run kept while the reference rests, the swing's amplitude
//! 2 |c| |vᵢ| (c = uᵀζ, the pair's coordinate) and what is left of the error once the swing's
//! share 2 Re(c vᵢ) is taken out. The swing grows or shrinks by |λ| per period whatever the rest
//! does: the student sees it take over, or die out. Buffers are kept between frames: nothing is
//! allocated once they are warm.

use super::drawing::{draw_series, PlotFrame};
use super::series::CURVE_WIDTH;
use crate::plot::palette;
use crate::schema::PanelKind;
use crate::view::painter::Painter;
use crate::view::panels::contract::RunState;

/// The split's points of the latest frame (times, the swing's amplitude, the rest).
#[derive(Clone, Debug, Default)]
pub struct SplitBuffers {
    time: Vec<f64>,
    swing: Vec<f64>,
    rest: Vec<f64>,
}

/// Curves the split adds to an error plot (for the vertex budget).
pub const SPLIT_SERIES: usize = 2;

impl SplitBuffers {
    /// Computes run A's split for an error plot (`kind` Error1 or Error2) of log |e| and draws the
    /// rest (under the error); [`SplitBuffers::draw_swing`] then draws the swing over it.
    pub fn draw_split(
        &mut self,
        painter: &mut Painter,
        frame: &PlotFrame,
        state: &RunState<'_>,
        kind: PanelKind,
        dpr: f64,
    ) {
        let component = match kind {
            PanelKind::Error1 => 0,
            PanelKind::Error2 => 1,
            _ => return,
        };
        let (history, reference, mode) =
            (state.history, state.reference, state.analysis.and_then(|r| r.swing_mode.as_ref()));
        let b = self;
        b.time.clear();
        b.swing.clear();
        b.rest.clear();
        let (Some(history), Some(reference), Some(mode)) = (history, reference, mode) else { return };
        let mut resting = false;
        for s in history.between(frame.window.start, frame.window.end) {
            let moving = reference.is_moving(s.time);
            if moving {
                // A gap while the reference moves: the split is about the rest point.
                if resting {
                    b.time.push(s.time);
                    b.swing.push(f64::NAN);
                    b.rest.push(f64::NAN);
                }
                resting = false;
                continue;
            }
            resting = true;
            let zeta = s.deviation(reference.target(s.time));
            let c = mode.coordinate(&zeta);
            let (share, amplitude) = mode.part(c, component);
            b.time.push(s.time);
            b.swing.push(amplitude);
            b.rest.push((zeta[component] - share).abs());
        }
        let w = CURVE_WIDTH * dpr;
        draw_series(painter, frame, &b.time, &b.rest, 0.75 * w, palette::SPLIT_REST);
    }

    /// Draws the swing of the split [`SplitBuffers::draw_split`] computed last, over the error.
    pub fn draw_swing(&self, painter: &mut Painter, frame: &PlotFrame, dpr: f64) {
        let b = self;
        let w = CURVE_WIDTH * dpr;
        draw_series(painter, frame, &b.time, &b.swing, 1.25 * w, palette::SWING);
    }
}
