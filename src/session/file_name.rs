//! What a downloaded file's name says of what it shows (issue 35): the preset, else run A's key
//! settings as they read in a link — so that a teacher's figures no longer share one name.

use super::settings::{run_pairs, Settings};

impl Settings {
    /// What a downloaded file's name says of run A's settings: its key settings as they read in a
    /// link, "delta0.02-alpha5-pf-off" (α as "alpha1-5-alpha2-2" when they differ).
    pub fn file_label(&self) -> String {
        let pairs = run_pairs(&self.a, false);
        let keys = ["delta", "alpha", "alpha1", "alpha2", "pf"];
        let parts: Vec<String> = keys
            .iter()
            .filter_map(|k| pairs.iter().find(|(key, _)| key == k))
            .map(|(k, v)| if matches!(*k, "delta" | "alpha") { format!("{k}{v}") } else { format!("{k}-{v}") })
            .collect();
        file_slug(&parts.join("-"))
    }
}

/// Letters, digits, dots and dashes only (a file name on every system).
pub fn file_slug(text: &str) -> String {
    let mut out = String::new();
    for c in text.chars() {
        if c.is_ascii_alphanumeric() || c == '.' {
            out.push(c.to_ascii_lowercase());
        } else if !out.ends_with('-') {
            out.push('-');
        }
    }
    out.trim_matches('-').to_string()
}
