// What the page adds to `window` (for the console and the end-to-end tests).
interface Window {
  flexarmPanic?: (message: unknown) => void;
  flexarm?: unknown;
  flexarmPerf?: () => unknown;
}
