// The page's one handle on the simulation: the physics session (runs, analyses, maps) and the
// classroom around it (the lesson, the answers, student mode, a link's moment, embeds) — two raw
// wasm bindings, Rust's `Session` and `Classroom` — composed as one typed object, as rapier.js
// puts a typed façade over its raw bindings. Every change the session makes itself is followed by
// the classroom (a lesson step's goal, what student mode hides); every classroom call is given the
// session. Nothing here decides anything: it composes and forwards. Type-checked strictly
// (`www/jsconfig.strict.json`).

/** @typedef {typeof import('../pkg/flexarm.js')} Wasm */
/** @typedef {import('../pkg/flexarm.js').Session} RawSession */
/** @typedef {import('../pkg/flexarm.js').Classroom} RawClassroom */
/** @typedef {import('../pkg/flexarm.js').Renderer} RawRenderer */

export class Page {
  /** @type {RawSession} */
  #session;
  /** @type {RawClassroom} */
  #classroom;

  /**
   * The page for the URL's query: the session's settings from it, then the lesson it names
   * (`lesson=3`, or a teacher's file: fetched, or carried by an offline file) and the link's moment.
   * @param {Wasm} wasm
   * @param {string} query
   * @param {string | undefined} lessonText the built-in lesson (`lessons/paper.md`)
   * @param {{ path: string, bytes: Uint8Array, carried: boolean, fragment?: string } | null | undefined} teacher a
   *   teacher's lesson file (`fragment`: the homework link's, when it came in one)
   * @param {boolean} [offline] the page is an offline file
   */
  constructor(wasm, query, lessonText, teacher, offline = false) {
    this.#session = new wasm.Session(query);
    this.#classroom = new wasm.Classroom(this.#session, query, lessonText, teacher?.path, teacher?.bytes, teacher?.carried ?? false, offline, teacher?.fragment);
  }

  /** The physics session, which the renderer draws. @returns {RawSession} */
  get session() {
    return this.#session;
  }

  /**
   * Runs a change of the session, then lets the classroom follow it.
   * @template T
   * @param {(s: RawSession) => T} fn
   * @returns {T}
   */
  #change(fn) {
    const out = fn(this.#session);
    this.#classroom.follow(this.#session);
    return out;
  }

  // ------------------------------------------------------------------------------- notices, status

  /** What the query could not take: the session's and the classroom's. @returns {{ key: string, text: string }[]} */
  notices() {
    return [...this.#session.notices(), ...this.#classroom.notices()];
  }

  /**
   * Everything the page says: the session's status with the classroom's lesson step and what
   * student mode hides (`lesson`, `hidden`). Brings the windows and the lesson's goal up to date.
   * @returns {any}
   */
  status() {
    const all = this.#classroom.status(this.#session);
    return { ...all.session, ...all.classroom };
  }

  /** The URL's query: the settings and the lesson step. @returns {string} */
  stateString() {
    return this.#classroom.stateString(this.#session);
  }

  /** @returns {any[]} */
  controls() {
    return this.#session.controls();
  }

  // ------------------------------------------------------------------------------------- settings
  // (Every text handed to the module goes through String(): the module reads strings only, and a
  // number given where it expects one corrupts its memory rather than throwing.)

  /**
   * A setting from its text (`set('delta', '0.05')`; a number is taken as its text: the module
   * reads strings only, and a number handed to it as one corrupts its memory).
   * @param {string} key @param {string | number} text
   */
  set(key, text) {
    this.#change((s) => s.set(String(key), String(text)));
  }

  /** @param {string} key @param {number} position */
  setPosition(key, position) {
    this.#change((s) => s.setPosition(String(key), position));
  }

  /** @param {string} key @param {number} steps */
  stepValue(key, steps) {
    this.#change((s) => s.stepValue(String(key), steps));
  }

  /** @param {string} id */
  applyPreset(id) {
    this.#change((s) => s.applyPreset(String(id)));
  }

  /** @param {string} state @returns {{ key: string, text: string }[]} */
  readState(state) {
    return this.#change((s) => s.readState(String(state)));
  }

  /** @param {string} side @param {number} delta @param {number} alpha */
  setFromMap(side, delta, alpha) {
    this.#change((s) => s.setFromMap(String(side), delta, alpha));
  }

  /** @param {string} side @param {number} deltaSteps @param {number} alphaSteps */
  stepOnMap(side, deltaSteps, alphaSteps) {
    this.#change((s) => s.stepOnMap(String(side), deltaSteps, alphaSteps));
  }

  /** @param {number} delta */
  pickDelta(delta) {
    this.#change((s) => s.pickDelta(delta));
  }

  /**
   * Places run A's flexible pair at re ± j im (1/s) with the twist feedback: its gains become the
   * settings. Returns "" when placed, else the session's reason (nothing changed).
   * @param {number} re @param {number} im @returns {string}
   */
  placePair(re, im) {
    return this.#refusal(() => this.#change((s) => s.placePair(re, im)));
  }

  /** Moves the pair's target by arrow-key steps; "" or why not. @param {number} reSteps @param {number} imSteps @returns {string} */
  nudgePair(reSteps, imSteps) {
    return this.#refusal(() => this.#change((s) => s.nudgePair(reSteps, imSteps)));
  }

  /** "" if `fn` ran, else its error's message (a refusal is an answer, not a failure). @param {() => void} fn */
  #refusal(fn) {
    try {
      fn();
      return '';
    } catch (e) {
      return e instanceof Error ? e.message : String(e);
    }
  }

  /** @param {string} which "whole" or "pair" */
  zView(which) {
    this.#change((s) => s.zView(String(which)));
  }

  /**
   * Zooms the z-plane by `factor` about (x, y) (CSS px of the canvas; NaN: the panel's centre);
   * the renderer writes the view into the session's settings. False when not on the z-plane.
   * @param {RawRenderer} renderer @param {number} x @param {number} y @param {number} factor
   * @returns {boolean}
   */
  zoomZ(renderer, x, y, factor) {
    return this.#change((s) => renderer.zoomZ(s, x, y, factor));
  }

  /**
   * Moves the z-plane by (dx, dy) CSS px, written into the session's settings.
   * @param {RawRenderer} renderer @param {number} dx @param {number} dy @returns {boolean}
   */
  panZ(renderer, dx, dy) {
    return this.#change((s) => renderer.panZ(s, dx, dy));
  }

  /** @param {string} note */
  setNote(note) {
    this.#session.setNote(String(note));
  }

  // ----------------------------------------------------------------------------------------- time

  /** @param {number} wallSeconds @returns {number} */
  advance(wallSeconds) {
    return this.#session.advance(wallSeconds);
  }

  stepPeriod() {
    this.#change((s) => s.stepPeriod());
  }

  reset() {
    this.#change((s) => s.reset());
  }

  poke() {
    this.#change((s) => s.poke());
  }

  /** @returns {boolean} */
  isFinished() {
    return this.#session.isFinished();
  }

  /**
   * The study of what bounds δ with run A's sensors, after up to `runs` more simulated slews.
   * @param {number} runs @returns {import('./sensors.js').SensorStudy}
   */
  sensorStudy(runs) {
    return this.#session.sensorStudy(runs);
  }

  /** True if the figure draws the sensor study (the page then runs it). @returns {boolean} */
  studyDrawn() {
    return this.#session.studyDrawn();
  }

  /**
   * The controller's time per sample in this browser, against run A's δ (Rust's words).
   * @returns {{ secondsPerSample: number, samplingPeriod: number, share: number, text: string }}
   */
  controllerTime() {
    return this.#session.controllerTime();
  }

  /** @param {number} t */
  viewAt(t) {
    this.#session.viewAt(t);
  }

  stepBack() {
    this.#session.stepBack();
  }

  continueFromHere() {
    this.#change((s) => s.continueFromHere());
  }

  /** @param {number} budgetMs @returns {boolean} */
  workMaps(budgetMs) {
    return this.#session.workMaps(budgetMs);
  }

  /** @returns {any[]} */
  mapTimes() {
    return this.#session.mapTimes();
  }

  /** The time shown, s. @returns {number} */
  time() {
    return this.#session.time();
  }

  /** One run's state at the time shown. @param {number} run @returns {any} */
  snapshot(run) {
    return this.#session.snapshot(run);
  }

  // -------------------------------------------------------------------------------------- exports

  /** @returns {string} */
  csv() {
    return this.#session.csv();
  }

  /** @returns {string} */
  commandLine() {
    return this.#session.commandLine();
  }

  /** @param {string} template @returns {string} */
  pythonScript(template) {
    return this.#session.pythonScript(template);
  }

  /** @returns {string} */
  dataCsv() {
    return this.#session.dataCsv();
  }

  /** What a download's name says of what it shows: "fig5.3", "delta0.02-alpha5-pf-off". @returns {string} */
  fileLabel() {
    return this.#session.fileLabel();
  }

  /**
   * A panel's figure, its caption with the whole state string (the classroom's), made as `options`
   * ask: `background=white&text=large&caption=settings&shape=wide&zview=RE,IM,HALF&dark=1`, every
   * key optional (Rust reads and checks them).
   * @param {string} panel @param {string} [options] @returns {string}
   */
  figureSvg(panel, options = '') {
    return this.#session.figureSvg(String(panel), this.stateString(), String(options));
  }

  /**
   * A class's answer files merged into one table, with the open lesson's steps where they answer
   * it (Rust's `classroom::class`, the same as `flexarm answers merge`).
   * @param {string[]} names @param {string[]} texts @returns {import('./class.js').Merged}
   */
  mergeAnswers(names, texts) {
    return this.#classroom.mergeAnswers(names.map(String), texts.map(String));
  }

  /** The caption under the page's picture: what it shows at which time, and the state string. @returns {string} */
  pictureCaption() {
    return this.#session.pictureCaption(this.stateString());
  }

  /** @returns {{ id: string, label: string }[]} */
  figurePanels() {
    return this.#session.figurePanels();
  }

  /** @param {string} pageUrl @param {string} choices @returns {any} */
  embed(pageUrl, choices) {
    return this.#classroom.embed(this.#session, pageUrl, choices);
  }

  /** @returns {string} */
  embedDefaults() {
    return this.#classroom.embedDefaults(this.#session);
  }

  /** @returns {boolean} */
  takeStartPaused() {
    return this.#classroom.takeStartPaused();
  }

  /** @returns {string} */
  momentQuery() {
    return this.#classroom.momentQuery(this.#session);
  }

  /**
   * The offline file (UTF-8 bytes) of `bundle`'s files, their archive gzipped (`compressed`),
   * opening where the page is now (and at this moment, if `paused`).
   * @param {import('../pkg/flexarm.js').OfflineBundle} bundle @param {Uint8Array} compressed @param {boolean} paused
   * @returns {Uint8Array}
   */
  offlineFile(bundle, compressed, paused) {
    return this.#classroom.offlineFile(this.#session, bundle, compressed, paused);
  }

  // ------------------------------------------------------------------------------------ the lesson

  /** Who answers: written into the answers handed in. @param {string} name */
  setStudent(name) {
    this.#classroom.setStudent(String(name));
  }

  /** The teacher's lesson loaded now, as a homework link carries it (null: the built-in one).
   * @returns {{ name: string, text: string } | null} */
  teacherLesson() {
    return this.#classroom.teacherLesson() ?? null;
  }

  /** @param {string} name @param {Uint8Array} bytes */
  loadLesson(name, bytes) {
    this.#classroom.loadLesson(this.#session, name, bytes);
  }

  /**
   * The lesson just opened from a file moves into the address (a reload keeps it): the fragment,
   * from its text compressed with raw deflate; throws when it is too long for an address.
   * @param {string} name @param {Uint8Array} compressed @returns {string}
   */
  carryInLink(name, compressed) {
    return this.#classroom.carryInLink(this.#session, name, compressed);
  }

  /** @param {number} step */
  lessonOpen(step) {
    this.#classroom.act(this.#session, 'open', step);
  }

  lessonNext() {
    this.#classroom.act(this.#session, 'next', 0);
  }

  lessonBack() {
    this.#classroom.act(this.#session, 'back', 0);
  }

  /** @param {number} choice */
  lessonAnswer(choice) {
    this.#classroom.act(this.#session, 'answer', choice);
  }

  lessonReveal() {
    this.#classroom.act(this.#session, 'reveal', 0);
  }

  lessonLeave() {
    this.#classroom.act(this.#session, 'leave', 0);
  }

  // ----------------------------------------------------------------------- answers, student mode

  /** @param {number} ms */
  setWallClock(ms) {
    this.#classroom.setWallClock(ms);
  }

  /** @returns {string} */
  answersCsv() {
    return this.#classroom.answersCsv();
  }

  /** @param {string} csv */
  restoreAnswers(csv) {
    this.#classroom.restoreAnswers(this.#session, String(csv));
  }

  clearAnswers() {
    this.#classroom.act(this.#session, 'clear', 0);
  }

  showAnswers() {
    this.#classroom.act(this.#session, 'show', 0);
  }

  /** Student mode back on for a lesson this browser kept it for. */
  keepStudentMode() {
    this.#classroom.act(this.#session, 'keep-student-mode', 0);
  }
}
