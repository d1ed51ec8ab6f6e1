//! Facts in words: the one place that turns what the analysis and the simulation found into
//! sentences, MathML and screen-reader text — for the page's status and explanation and the CLI's
//! summaries alike, one wording per fact. The layers below return values (a [`Verdict`], a
//! [`crate::analysis::judgement::Judgement`], a report's numbers), never English.
//!
//! | module | says |
//! |---|---|
//! | [`verdict`] | the simulation's verdict, its growth rate, why a run diverged |
//! | [`judgement`] | a run's judgement: headline, ρ's prediction, what was observed and why, the analysis line |
//! | [`design`] | the preliminary feedback as a design: its pair, its price analog and sampled, in torque, its parts |
//! | [`structure`] | section 3's structure for the arm shown: V*, the zero dynamics, A4, the index, k |
//! | [`story`] | the explanation's live numbers, from run A's analysis |
//! | [`equations`] | the same numbers as MathML equations |
//! | [`settings`] | a run's settings, its feedback, a map's caption, a point of it, the errors, the stable windows of δ |
//! | [`panels`] | the panels a small canvas leaves out, and where they are |
//! | [`work`] | what a run will cost, a duration in sensible units |
//! | [`processor`] | how long the controller's prediction takes against δ: faster than real time or not |
//! | [`numbers`] | numbers as the sentences write them (rates, ρ, percents, pairs, the swing's energy shares) |
//!
//! [`Verdict`]: crate::control::Verdict

pub mod design;
pub mod equations;
pub mod judgement;
pub mod numbers;
pub mod panels;
pub mod processor;
pub mod sensors;
pub mod settings;
pub mod story;
pub mod structure;
pub mod verdict;
pub mod work;
