// The teacher's side of the answers (issue 35): a class's answer files, chosen or dropped on the
// page, merged into one table — per step the share right at the first try, the wrong choices most
// made, the tasks — with every file that cannot count named and why. The merge and its words are
// Rust's (`classroom::class`, the same as `flexarm answers merge`); nothing leaves the browser.

import { byId, make, setText } from './dom.js';

/**
 * @typedef {{ step: number, title: string }} StepTally
 * @typedef {{ lesson: string, counted: [string, string][], refused: [string, string][], steps: StepTally[],
 *   rows: [string, string, string][], student_rows: string[][], summary: string,
 *   csv: string, students_csv: string }} Merged
 * @param {{ merge: (names: string[], texts: string[]) => Merged,
 *   download: (name: string, text: string, type: string) => void, report: (what: string, e: unknown) => void }} on
 */
export function createClassTable(on) {
  const box = byId('class-table');
  const dialog = /** @type {HTMLDialogElement} */ (byId('class-dialog'));
  /** @type {Merged | null} */
  let shown = null;
  byId('class-download').addEventListener('click', () => {
    if (shown) on.download('flexarm-class-answers.csv', shown.csv, 'text/csv');
  });
  byId('class-download-students').addEventListener('click', () => {
    if (shown) on.download('flexarm-class-students.csv', shown.students_csv, 'text/csv');
  });
  const open = () => {
    if (!dialog.open) dialog.showModal();
  };
  byId('class-close').addEventListener('click', () => dialog.close());
  byId('class-show').addEventListener('click', open);
  // A click on the backdrop (outside the table) closes it too.
  dialog.addEventListener('click', (e) => {
    if (e.target === dialog) dialog.close();
  });

  /** Reads and merges `files`, and shows the table. @param {File[]} files */
  async function merge(files) {
    try {
      const texts = await Promise.all(files.map((f) => f.text()));
      shown = on.merge(files.map((f) => f.name), texts);
    } catch (e) {
      on.report('The answer files could not be merged', e);
      return;
    }
    const m = shown;
    setText(byId('class-title'), m.lesson ? `Your class: ${m.lesson}` : 'Your class');
    setText(byId('class-summary'), `${m.counted.length} answer file${m.counted.length === 1 ? '' : 's'} counted, ${m.refused.length} not.`);
    byId('class-rows').replaceChildren(
      ...m.steps.map((s, i) => make('tr', {}, [
        make('th', { scope: 'row', text: `${s.step}. ${s.title}` }),
        ...m.rows[i].map((cell) => make('td', { text: cell })),
      ])),
    );
    // Who counted, by the name each file gives (its file name where it gives none), and how each
    // did: the score, then a column per step (its title on the number); the files that did not.
    byId('class-students-head').replaceChildren(
      make('th', { scope: 'col', text: 'Student' }),
      make('th', { scope: 'col', text: 'Right at the first try' }),
      ...m.steps.map((s) => make('th', { scope: 'col', class: 'class-step', text: String(s.step), title: s.title })),
    );
    byId('class-students').replaceChildren(
      ...m.student_rows.map(([name, file, right, ...marks]) => make('tr', {}, [
        make('th', { scope: 'row', text: name, title: file }),
        make('td', { text: right }),
        ...marks.map((mark) => make('td', { class: 'class-step', text: mark })),
      ])),
      ...m.refused.map(([name, why]) => make('tr', { class: 'class-not-counted' }, [
        make('th', { scope: 'row', text: name }),
        make('td', { colspan: String(m.steps.length + 1), text: `not counted: ${why}` }),
      ])),
    );
    byId('class-refused').replaceChildren(...m.refused.map(([name, why]) => make('li', { text: `Not counted: ${name} — ${why}` })));
    box.hidden = false;
    byId('class-reopen').hidden = false;
    open();
  }

  return { merge };
}
