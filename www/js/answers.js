// The lesson's answers to hand in, and student mode's notice. What counts (right, done, shown),
// the summary's words and the CSV are the session's (Rust); this keeps the record in the browser
// (localStorage, under the lesson text's hash, as the CSV it downloads — never sent anywhere),
// gives it back after a reload, and offers the downloads and "Clear my answers".

import { byId, make, setText } from './dom.js';

/** Where a lesson's record is kept: one key per lesson text (pure). @param {string} hash */
export function storageKey(hash) {
  return `flexarm.answers.${hash}`;
}

/** Where student mode is kept for a lesson text: once on, a reload (or the address without
 * `answers=hidden`) keeps it, until "Clear my answers" (pure). @param {string} hash */
export function studentModeKey(hash) {
  return `flexarm.student-mode.${hash}`;
}

/** Letters, digits and dashes only, at most 40 (pure). @param {string} text */
function slugOf(text) {
  return text.toLowerCase().normalize('NFKD').replace(/[^a-z0-9]+/g, '-').replace(/^-+|-+$/g, '').slice(0, 40);
}

/** The download's file name for a lesson title and the student's name (pure): letters, digits
 * and dashes only, so that a teacher's 60 files do not share one name. */
export function answersFileName(/** @type {string} */ title, /** @type {string} */ ext, name = '') {
  const who = slugOf(name);
  return `flexarm-answers-${slugOf(title) || 'lesson'}${who ? `-${who}` : ''}.${ext}`;
}

/** Where the student's name is kept: asked once, for every lesson. */
export const STUDENT_KEY = 'flexarm.student';

/** "05:19:43 UTC" from an ISO 8601 UTC time (pure). @param {string} iso */
export function clock(iso) {
  const m = /T(\d\d:\d\d:\d\d)Z$/.exec(iso);
  return m ? `${m[1]} UTC` : iso;
}

/** One CSV line's cells, quotes undone (pure): the record's own quoting. @param {string} line */
export function csvCells(line) {
  const cells = [];
  let cell = '';
  let quoted = false;
  for (let i = 0; i < line.length; i++) {
    const c = line[i];
    if (c === '"' && quoted && line[i + 1] === '"') {
      cell += '"';
      i++;
    } else if (c === '"') quoted = !quoted;
    else if (c === ',' && !quoted) {
      cells.push(cell);
      cell = '';
    } else cell += c;
  }
  cells.push(cell);
  return cells;
}

/**
 * The answers' CSV as JSON (pure): the comment line, and one object per row named by the
 * header's columns (numbers for step and choice). The same rows as the CSV, reshaped.
 * @param {string} csv
 */
export function answersJson(csv) {
  const lines = csv.split('\n').filter((l) => l !== '');
  const head = lines.filter((l) => l.startsWith('#')).map((l) => l.replace(/^# ?/, ''));
  const [columns, ...rows] = lines.filter((l) => !l.startsWith('#')).map(csvCells);
  const entries = rows.map((cells) =>
    Object.fromEntries((columns ?? []).map((c, i) => [c, (c === 'step' || c === 'choice') && cells[i] !== '' ? Number(cells[i]) : cells[i] ?? ''])),
  );
  return { head, entries };
}

/**
 * @typedef {{ headline: string, rows: { text: string, result: string, state: string, time: string }[],
 *   count: number, lesson_hash: string }} AnswersStatus
 * @param {{ session: import('./flexarm.js').Page, presets: { id: string, title: string, settings_title: string }[],
 *   report: (what: string, e: unknown) => void,
 *   download: (name: string, text: string, type: string) => void, changed: () => void }} on
 */
export function createAnswers(on) {
  const box = /** @type {HTMLDetailsElement} */ (byId('lesson-record'));
  const summary = byId('lesson-record-summary');
  const headline = byId('lesson-record-headline');
  const rows = byId('lesson-record-rows');
  const hiddenNote = byId('hidden-note');
  /** The hash whose saved record was looked for, and the count last saved. */
  let restored = '';
  let saved = -1;
  let shownKey = '';
  let lastStep = -1;
  let presetsHidden = false;
  let hiddenKey = '[]';
  /** @type {{ title: string } | null} */
  let current = null;

  /** localStorage, or null where the browser refuses it (private mode, a sandboxed frame). */
  const storage = () => {
    try {
      return window.localStorage;
    } catch {
      return null;
    }
  };

  // The name, asked once (kept in this browser for every lesson) and written into the answers.
  const nameField = /** @type {HTMLInputElement} */ (byId('student-name'));
  nameField.value = storage()?.getItem(STUDENT_KEY) ?? '';
  const giveName = () => {
    try {
      on.session.setStudent(nameField.value);
    } catch (e) {
      on.report('That name cannot go with your answers', e);
    }
  };
  nameField.addEventListener('change', () => {
    try {
      storage()?.setItem(STUDENT_KEY, nameField.value.trim());
    } catch {
      // Kept for this visit only.
    }
    giveName();
    saved = -1;
    on.changed();
  });
  byId('answers-json').addEventListener('click', () => {
    const json = answersJson(on.session.answersCsv());
    on.download(answersFileName(current?.title ?? '', 'json', nameField.value), `${JSON.stringify(json, null, 2)}\n`, 'application/json');
  });
  byId('answers-csv').addEventListener('click', () => {
    on.download(answersFileName(current?.title ?? '', 'csv', nameField.value), on.session.answersCsv(), 'text/csv');
  });
  // Clearing asks twice, in the button itself (no dialog): a first click arms it for a few seconds.
  const clear = /** @type {HTMLButtonElement} */ (byId('answers-clear'));
  let armed = 0;
  clear.addEventListener('click', () => {
    if (!armed) {
      setText(clear, 'Click again to clear them all');
      armed = window.setTimeout(() => {
        armed = 0;
        setText(clear, 'Clear my answers');
      }, 4000);
      return;
    }
    window.clearTimeout(armed);
    armed = 0;
    setText(clear, 'Clear my answers');
    try {
      on.session.clearAnswers();
    } catch (e) {
      on.report('Clearing the answers failed', e);
      return;
    }
    if (restored) {
      storage()?.removeItem(storageKey(restored));
      storage()?.removeItem(studentModeKey(restored));
    }
    saved = 0;
    on.changed();
  });
  byId('show-answers').addEventListener('click', () => {
    on.session.showAnswers();
    on.changed();
  });

  /**
   * Follows the session's status: gives back a record kept earlier when a lesson first shows,
   * keeps the record when it changes, shows the summary (open at the last step) and student
   * mode's notice.
   * @param {{ lesson_title: string, index: number, steps: string[], record: AnswersStatus, student_mode: boolean } | null} lesson
   * @param {{ text: string, controls: string[] } | null} hidden
   */
  function sync(lesson, hidden) {
    hiddenNote.hidden = !hidden;
    document.body.classList.toggle('answers-hidden', Boolean(hidden));
    setText(byId('hidden-text'), hidden?.text ?? '');
    // The figures' presets by their settings only, while what they show is hidden.
    if (presetsHidden !== Boolean(hidden)) {
      presetsHidden = Boolean(hidden);
      for (const option of /** @type {HTMLSelectElement} */ (byId('preset')).options) {
        const p = on.presets.find((x) => x.id === option.value);
        if (p) option.text = hidden ? p.settings_title : p.title;
      }
    }
    // What shows nothing while hidden is disabled (the session names it), and enabled again after.
    if (hiddenKey !== JSON.stringify(hidden?.controls ?? [])) {
      for (const id of JSON.parse(hiddenKey)) {
        const el = /** @type {HTMLInputElement | null} */ (document.getElementById(id));
        if (el && 'disabled' in el) el.disabled = false;
      }
      hiddenKey = JSON.stringify(hidden?.controls ?? []);
      for (const id of hidden?.controls ?? []) {
        const el = /** @type {HTMLInputElement | null} */ (document.getElementById(id));
        if (el && 'disabled' in el) el.disabled = true;
      }
    }
    // A student's page: the teacher's tools (a lesson file, a homework link, merging) step aside.
    document.body.classList.toggle('student-mode', Boolean(lesson?.student_mode));
    if (!lesson) return;
    current = { title: lesson.lesson_title };
    const { record: r } = lesson;
    const modeKey = studentModeKey(r.lesson_hash);
    if (restored !== r.lesson_hash) {
      restored = r.lesson_hash;
      if (nameField.value) giveName();
      // Student mode, kept for this lesson: nothing the lesson hides shows after a reload.
      const keep = !lesson.student_mode && Boolean(storage()?.getItem(modeKey));
      if (keep) on.session.keepStudentMode();
      saved = r.count;
      const text = storage()?.getItem(storageKey(r.lesson_hash));
      if (text) {
        try {
          on.session.restoreAnswers(text);
          saved = -1;
          on.changed();
          return;
        } catch (e) {
          on.report('Your saved answers could not be given back (they stay in the browser)', e);
        }
      }
      if (keep) {
        on.changed();
        return;
      }
    }
    if (lesson.student_mode && !storage()?.getItem(modeKey)) {
      try {
        storage()?.setItem(modeKey, '1');
      } catch {
        // Kept by the address alone.
      }
    }
    if (r.count !== saved) {
      saved = r.count;
      try {
        storage()?.setItem(storageKey(r.lesson_hash), on.session.answersCsv());
      } catch (e) {
        on.report('Your answers could not be kept in this browser (download them instead)', e);
      }
    }
    const last = lesson.index === lesson.steps.length - 1;
    if (lesson.index !== lastStep) {
      lastStep = lesson.index;
      // The summary opens by itself at the end of the lesson.
      box.open = last;
    }
    const key = JSON.stringify([r.headline, r.count]);
    if (key === shownKey) return;
    shownKey = key;
    setText(summary, `Your answers (${r.count})`);
    setText(headline, r.headline);
    rows.replaceChildren(
      ...r.rows.map((row) =>
        make('li', { class: `record-${row.result}` }, [
          make('span', { text: row.text }),
          make('span', { class: 'record-state' }, [
            document.createTextNode(row.time ? ` — ${clock(row.time)} · ` : ' — '),
            // The settings it was made in: a link back to that step as it was.
            make('a', { href: `?${row.state}`, title: row.state, text: 'its settings' }),
          ]),
        ]),
      ),
    );
  }

  return { sync };
}
