//! The offline file's binding: the page gathers its files into an [`OfflineBundle`](WebBundle)
//! (it names each file it wants next), compresses the archive with the browser's
//! `CompressionStream`, and the classroom writes the file with the page's start
//! (`Classroom.offlineFile`).

use wasm_bindgen::prelude::*;

use super::js_error;
use crate::offline::{Bundle, CarriedLesson, OfflineStart};

/// The files of one offline file, gathered one by one.
#[wasm_bindgen(js_name = OfflineBundle)]
pub struct WebBundle {
    pub(crate) inner: Bundle,
}

#[wasm_bindgen(js_class = OfflineBundle)]
impl WebBundle {
    /// A bundle that wants the page and the files it reads by path.
    #[wasm_bindgen(constructor)]
    pub fn new() -> WebBundle {
        WebBundle { inner: Bundle::new() }
    }

    /// The path (relative to the page) of the next file the bundle needs; undefined once it has all.
    #[wasm_bindgen(js_name = nextWanted)]
    pub fn next_wanted(&self) -> Option<String> {
        self.inner.next_wanted().map(str::to_string)
    }

    /// Gives the bundle the file it wants at `path`; throws with the reason.
    pub fn add(&mut self, path: &str, bytes: Vec<u8>) -> Result<(), JsError> {
        self.inner.add(path, bytes).map_err(js_error)
    }

    /// The archive of the files the page reads as it runs, uncompressed (the page gzips it).
    pub fn archive(&self) -> Result<Vec<u8>, JsError> {
        self.inner.archive().map_err(js_error)
    }

    /// An offline file's start in words ("δ = 0.01 s …; paused at t = 3 s; student mode"), from
    /// what the file carries.
    pub fn describe(query: &str, lesson_name: Option<String>, lesson_text: Option<String>) -> String {
        let lesson = lesson_name.zip(lesson_text).map(|(name, text)| CarriedLesson { name, text });
        OfflineStart { query: query.to_string(), lesson }.describe()
    }

    /// What the page says beside "Save for offline": the file's size and what it is.
    #[wasm_bindgen(js_name = sizeText)]
    pub fn size_text(file_bytes: usize, compressed_bytes: usize) -> String {
        crate::offline::size_text(file_bytes, compressed_bytes)
    }
}

impl Default for WebBundle {
    fn default() -> Self {
        Self::new()
    }
}
