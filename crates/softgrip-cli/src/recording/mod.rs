//! Reading a recording for `inspect`, `export` and `plot`: opening it with a one-line error,
//! and the per-contact samples and law parameters the three commands share.

mod export;
mod inspect;
mod plot;
mod recover;

pub use export::{ExportArgs, export};
pub use inspect::{InspectArgs, inspect};
pub use plot::{PlotArgs, plot};
pub use recover::{RecoverArgs, recover};

use std::path::Path;

use anyhow::{Result, anyhow};
use softgrip_record::msgs::softgrip_msgs::SoftContactMsg;
use softgrip_record::{FingertipLaw, Message, Recording, RecordingInfo, topics};

/// Opens a recording; any failure (missing, not MCAP, truncated before the magic, corrupt) is
/// one line naming the file.
pub fn open(path: &Path) -> Result<Recording> {
    Recording::open(path).map_err(|e| {
        let msg = e.to_string().replace('\n', " ");
        // Io errors already name the path.
        if msg.starts_with(&path.display().to_string()) {
            anyhow!("{msg}")
        } else {
            anyhow!("{}: {msg}", path.display())
        }
    })
}

/// Log time \[ns\] as seconds.
pub fn seconds(ns: u64) -> f64 {
    ns as f64 * 1e-9
}

/// Every recorded contact with its log time \[s\], in file order.
pub fn contacts(rec: &Recording) -> impl Iterator<Item = (f64, &SoftContactMsg)> {
    rec.on_topic(topics::CONTACTS).flat_map(|m| {
        let t = seconds(m.log_time_ns);
        match &m.message {
            Message::Contacts(a) => a.contacts.iter().map(move |c| (t, c)).collect::<Vec<_>>(),
            _ => Vec::new(),
        }
    })
}

/// What the recording is of (its typed `softgrip` metadata record; the defaults when absent
/// or unreadable, with a warning for the latter).
pub fn info(rec: &Recording) -> RecordingInfo {
    rec.info()
        .unwrap_or_else(|e| {
            eprintln!("warning: {e}");
            None
        })
        .unwrap_or_default()
}

/// The per-fingertip law parameters of the metadata (empty when absent or unreadable).
pub fn laws(rec: &Recording) -> Vec<FingertipLaw> {
    rec.info().ok().flatten().map(|i| i.law).unwrap_or_default()
}

/// Fingertip names: those of the metadata, then any other seen in the contacts.
pub fn fingertips(rec: &Recording) -> Vec<String> {
    let mut names: Vec<String> = laws(rec).into_iter().map(|l| l.name).collect();
    for (_, c) in contacts(rec) {
        if !names.contains(&c.fingertip) {
            names.push(c.fingertip.clone());
        }
    }
    names
}

/// The contact radius of a recorded contact: the recorded one when the scene recorded
/// pressure, otherwise the law's at the recorded compression (when the metadata has the law).
pub fn contact_radius(c: &SoftContactMsg, law: Option<&softgrip_law::ContactLaw>) -> f64 {
    if c.contact_radius > 0.0 {
        return c.contact_radius;
    }
    law.map_or(0.0, |l| l.patch(c.compression).radius)
}
