// Whole numbers in the page's English sentences, with a comma between thousands ("1,000,000").
// Not toLocaleString: its first call loads the browser's locale data, about 25 ms of the main
// thread, and progress-schema.js builds its messages as the page starts.

/** A non-negative whole number as "12,345". */
export const groupDigits = (n) => String(n).replace(/\B(?=(\d{3})+(?!\d))/g, ",");
