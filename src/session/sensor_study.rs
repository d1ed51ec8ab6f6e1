//! What bounds δ from below with run A's sensors (issue 36): the study of
//! [`crate::analysis::sensor_study`] as a job the page runs a little at a time — one simulated
//! slew per call, so the table fills while the page stays live — and restarts when a setting it
//! depends on changes (anything of run A but δ, which the study sweeps).

use super::sensor_study_job::SensorStudyView;
use super::Session;
use crate::analysis::sensor_study::{Best, SensorStudy, STUDY_DELTAS};
use crate::control::config::SimulationConfig;
use crate::control::sensor_sweep::SensorSweep;
use crate::error::Error;
use crate::words::sensors::{prediction_text, sensors_text, study_summary, study_table, table_note};

/// Run A's configuration with δ normalized away: the study's key.
fn study_key(config: &SimulationConfig) -> SimulationConfig {
    let mut c = *config;
    c.controller.sampling_period = STUDY_DELTAS[0];
    c
}

impl Session {
    /// True if the figure draws the study (the `study` switch, with run A's sensors digital): the
    /// page then runs it whether or not its section is open.
    pub fn study_drawn(&self) -> bool {
        self.drawn_view().study && self.settings.a.config().sensors.is_digital()
    }

    /// True if run A's running controller reads sensors (a digital controller): the velocity panel
    /// and the study have something to show in a figure.
    pub fn reads_sensors(&self) -> bool {
        self.run(0).is_some_and(|r| r.closed_loop().config().sensors.is_digital())
    }

    /// The study's generation: it moves with every start and every run done (cheap; the figure
    /// asks every frame and takes [`Self::study_facts`] only when it moved).
    pub fn study_generation(&self) -> u64 {
        self.sensor_study.generation
    }

    /// The study's facts so far, if it is run A's current one: what the figure draws. None before
    /// it starts or after run A's settings other than δ changed (until the next step starts it
    /// over).
    pub fn study_facts(&self) -> Option<SensorStudy> {
        let job = &self.sensor_study;
        let current = job.key == Some(study_key(&self.settings.a.config()));
        job.sweep.as_ref().filter(|_| current).map(|sweep| SensorStudy::of(sweep, &job.linear))
    }

    /// Advances the study of run A's sensors by up to `runs` simulated slews (0: only report),
    /// starting it over if run A's settings other than δ changed; returns where it stands.
    pub fn sensor_study_step(&mut self, runs: usize) -> Result<SensorStudyView, Error> {
        let config = self.settings.a.config();
        let key = study_key(&config);
        let job = &mut self.sensor_study;
        if job.key != Some(key) || job.sweep.is_none() {
            job.sweep = Some(SensorSweep::new(key, &STUDY_DELTAS)?);
            job.linear = SensorStudy::linear(&key, &STUDY_DELTAS);
            job.key = Some(key);
            job.generation += 1;
        }
        let sweep = job.sweep.as_mut().ok_or(Error::Analysis("no study"))?;
        for _ in 0..runs {
            if !sweep.step()? {
                break;
            }
            job.generation += 1;
        }
        let study = SensorStudy::of(sweep, &job.linear);
        let delta = config.controller.sampling_period;
        // The same floor as the status under the verdict: run A's analysis, scaled.
        let floor = self.a.analysis().unit_floor().map(|f| f.scaled(config.sensors.angle_variance().sqrt()));
        let current_row = STUDY_DELTAS
            .iter()
            .enumerate()
            .min_by(|a, b| (a.1.ln() - delta.ln()).abs().total_cmp(&(b.1.ln() - delta.ln()).abs()))
            .map_or(0, |(i, _)| i);
        Ok(SensorStudyView {
            sensors: sensors_text(&config.sensors),
            table: study_table(&study, &config.sensors),
            table_note: table_note(&config.sensors),
            best_row: match study.best {
                Best::Inside { index } | Best::Smallest { index } => Some(index),
                _ => None,
            },
            current_row,
            deltas: STUDY_DELTAS.to_vec(),
            summary: study_summary(&study, &config.sensors),
            prediction: prediction_text(delta, floor.as_ref(), &config.sensors),
            done: sweep.is_done(),
            progress: study.progress,
            study,
        })
    }
}
