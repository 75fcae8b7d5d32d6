// A worked answer's output is folded twice in the instructor's book: by the book's own fold around the
// cell (its "Answer" bar) and by the fold the notebook gives it ("#| answer", which keeps it hidden in
// JupyterLab and the lecture-room app). One fold is enough here: the inner one opens with the page.
document.addEventListener('DOMContentLoaded', () => {
  for (const fold of document.querySelectorAll('.tag_hide-cell details.raildyn-answer')) fold.open = true;
});
