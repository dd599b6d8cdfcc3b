// The report's script (report_pages.h): the before/after slider and sorting tables by
// any column. Every page reads the same without it.
"use strict";

// The slider clips the technique's image (drawn over the reference) to the left of the split.
function setUpSlider(slider) {
  const before = slider.querySelector(".slider-before");
  const split = slider.querySelector(".slider-split");
  const clip = () => { before.style.clipPath = `inset(0 ${100 - Number(split.value)}% 0 0)`; };
  split.addEventListener("input", clip);
  clip();
  slider.hidden = false;
}

// A cell's sort key: its data-value as a number ("" is n/a and sorts last), else its text.
function sortKey(cell) {
  if (cell.dataset.value === undefined) return cell.textContent.trim();
  return cell.dataset.value === "" ? NaN : Number(cell.dataset.value);
}

function compareKeys(a, b) {
  if (typeof a === "number" && typeof b === "number") {
    if (Number.isNaN(a) || Number.isNaN(b)) return Number.isNaN(a) - Number.isNaN(b);
    return a - b;
  }
  return String(a).localeCompare(String(b), undefined, { numeric: true });
}

// Ascending on the first click, then each click the other way; equal keys keep their order.
function sortBy(table, header, column) {
  const ascending = header.getAttribute("aria-sort") !== "ascending";
  for (const th of table.tHead.rows[0].cells) th.removeAttribute("aria-sort");
  header.setAttribute("aria-sort", ascending ? "ascending" : "descending");
  const body = table.tBodies[0];
  const rows = Array.from(body.rows).map((row, index) => ({ row, index, key: sortKey(row.cells[column]) }));
  rows.sort((a, b) => {
    const order = compareKeys(a.key, b.key);
    if (order !== 0 && !(Number.isNaN(a.key) || Number.isNaN(b.key))) return ascending ? order : -order;
    return order !== 0 ? order : a.index - b.index;
  });
  for (const { row } of rows) body.appendChild(row);
}

function makeSortable(table) {
  Array.from(table.tHead.rows[0].cells).forEach((header, column) => {
    const button = document.createElement("button");
    button.type = "button";
    button.textContent = header.textContent;
    button.title = "sort by " + header.textContent;
    button.addEventListener("click", () => sortBy(table, header, column));
    header.replaceChildren(button);
  });
}

document.querySelectorAll(".slider").forEach(setUpSlider);
document.querySelectorAll("table.sortable").forEach(makeSortable);
