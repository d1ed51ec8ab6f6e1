// The guided lesson's panel: the step the session says is open — its text, terms, task, question
// and (once answered) the answer — and the buttons that walk it. Which step, what it sets up and
// what counts as done are the session's (Rust; the text is www/lessons/paper.md); this only shows and routes.

import { byId, make, setText } from './dom.js';

/**
 * @typedef {{ prompt: string, choices: string[], chosen: number | null, correct: number | null }} Question
 * @typedef {{ lesson_title: string, source: string, steps: string[], index: number, title: string, text: string[],
 *   terms: { term: string, definition: string }[], task: string | null, done: boolean,
 *   question: Question | null, answer: string[], can_back: boolean, can_next: boolean, waits: boolean, student_mode: boolean,
 *   record: import('./answers.js').AnswersStatus }} LessonStatus
 */

/** How a choice is marked once the student has chosen (pure): its words for a screen reader too. */
export function choiceMark(/** @type {Question} */ q, /** @type {number} */ i) {
  if (q.chosen == null) return { cls: '', note: '' };
  if (i === q.correct) return { cls: 'right', note: i === q.chosen ? ' — your prediction, right' : ' — the right answer' };
  if (i === q.chosen) return { cls: 'wrong', note: ' — your prediction' };
  return { cls: '', note: '' };
}

/**
 * @param {{ start: () => void, next: () => void, back: () => void, leave: () => void,
 *   answer: (choice: number) => void, reveal: () => void, open: (file: File) => void,
 *   merge: (files: File[]) => void }} on
 */
export function createLesson(on) {
  const panel = byId('lesson');
  const title = byId('lesson-title');
  const question = byId('lesson-question');
  const choices = byId('lesson-choices');
  const task = byId('lesson-task');
  const taskDone = byId('lesson-task-done');
  const reveal = /** @type {HTMLButtonElement} */ (byId('lesson-reveal'));
  const back = /** @type {HTMLButtonElement} */ (byId('lesson-back'));
  const next = /** @type {HTMLButtonElement} */ (byId('lesson-next'));
  const start = byId('lesson-start');
  let shownStep = -1;
  let shownKey = '';

  start.addEventListener('click', on.start);
  back.addEventListener('click', on.back);
  next.addEventListener('click', on.next);
  byId('lesson-leave').addEventListener('click', on.leave);
  reveal.addEventListener('click', on.reveal);
  // A teacher's lesson file: chosen here, or dropped anywhere on the page.
  const file = /** @type {HTMLInputElement} */ (byId('lesson-file'));
  byId('lesson-file-open').addEventListener('click', () => file.click());
  file.addEventListener('change', () => {
    if (file.files?.[0]) on.open(file.files[0]);
    file.value = '';
  });
  document.addEventListener('dragover', (e) => {
    if (e.dataTransfer?.types.includes('Files')) e.preventDefault();
  });
  // A class's answer files (several, or CSV): merged; one Markdown file: a lesson.
  const classFiles = /** @type {HTMLInputElement} */ (byId('class-files'));
  byId('class-files-open').addEventListener('click', () => classFiles.click());
  classFiles.addEventListener('change', () => {
    if (classFiles.files?.length) on.merge([...classFiles.files]);
    classFiles.value = '';
  });
  document.addEventListener('drop', (e) => {
    const dropped = [...(e.dataTransfer?.files ?? [])];
    if (dropped.length === 0) return;
    e.preventDefault();
    if (dropped.length > 1 || /\.csv$/iu.test(dropped[0].name)) on.merge(dropped);
    else on.open(dropped[0]);
  });

  /** Shows the session's lesson status (null: the lesson is closed). @param {LessonStatus | null} s */
  function render(s) {
    panel.hidden = !s;
    document.body.classList.toggle('in-lesson', Boolean(s));
    setText(start, s ? 'Restart the lesson' : 'Start the lesson');
    if (!s) {
      shownStep = -1;
      shownKey = '';
      return;
    }
    // Another lesson (a teacher's file) is another key, even at the same step.
    const key = JSON.stringify([s.source, s.lesson_title, s.index, s.title, s.question?.chosen, s.done, s.answer.length, s.waits]);
    if (key === shownKey) return;
    shownKey = key;
    setText(byId('lesson-count'), `Step ${s.index + 1} of ${s.steps.length}`);
    setText(byId('lesson-name'), s.source ? `${s.lesson_title} (from ${s.source})` : s.lesson_title);
    setText(title, s.title);
    byId('lesson-text').replaceChildren(...s.text.map((p) => make('p', { text: p })));
    byId('lesson-terms').replaceChildren(...s.terms.flatMap((t) => [make('dt', { text: t.term }), make('dd', { text: t.definition })]));
    task.hidden = !s.task;
    setText(byId('lesson-task-text'), s.task ?? '');
    setText(taskDone, s.done ? '✓ Done.' : 'Not yet.');
    taskDone.classList.toggle('done', s.done);
    reveal.hidden = s.done;
    renderQuestion(s.question);
    byId('lesson-answer').replaceChildren(...s.answer.map((p) => make('p', { text: p })));
    back.disabled = !s.can_back;
    next.disabled = !s.can_next;
    // A lesson that waits for each answer says so on the button (the session decides).
    setText(next, s.waits ? 'Answer to go on' : s.can_next ? 'Next ▸' : 'Last step');
    if (s.index !== shownStep) {
      shownStep = s.index;
      // A new step: its title takes the focus (screen readers read it) and comes into view; the
      // figure beside it stays where it is.
      title.focus({ preventScroll: true });
      if (panel.getBoundingClientRect().top < 0) panel.scrollIntoView({ block: 'start' });
      // Where the controls' panel scrolls by itself (a phone's sheet), from its top, where the
      // lesson is: the step's title first.
      const sheet = panel.parentElement;
      requestAnimationFrame(() => { if (sheet) sheet.scrollTop = 0; });
    }
  }

  /** @param {Question | null} q */
  function renderQuestion(q) {
    question.hidden = !q;
    if (!q) return;
    setText(byId('lesson-prompt'), q.prompt);
    const name = 'lesson-choice';
    choices.replaceChildren(
      ...q.choices.map((text, i) => {
        const id = `lesson-choice-${i}`;
        const mark = choiceMark(q, i);
        // A prediction is made once: after it, the choices show the answer and stay as they are.
        const input = make('input', { type: 'radio', name, id, value: String(i), checked: q.chosen === i, disabled: q.chosen != null });
        input.addEventListener('change', () => on.answer(i));
        return make('div', { class: `choice ${mark.cls}`.trim() }, [input, make('label', { for: id, text: `${text}${mark.note}` })]);
      }),
    );
  }

  /**
   * Says what is wrong with the lesson file just opened, beside its button ('' clears it); false
   * when the lesson's panel is closed (a file dropped before the lesson was opened), where the
   * caller says it instead.
   * @param {string} text
   */
  function fileError(text) {
    const box = byId('lesson-file-error');
    setText(box, text);
    box.hidden = !text;
    if (!text) return true;
    if (panel.hidden) return false;
    console.warn(text);
    // A file dropped anywhere: the message comes into view where the lesson's files are.
    box.scrollIntoView({ block: 'nearest' });
    return true;
  }

  return { render, fileError };
}
