// Numbers as the CLI prints them, for the figures the page shows beside the CLI's.

/** x with `digits` decimals as C's printf("%.*f") writes it (so as `hbc table` and `hbc analyze`
 *  do): the double's exact value rounded, an exact tie to the even neighbour. Number.toFixed rounds
 *  a tie away from zero: 1/32 is 0.0313 there, 0.0312 in the CLI. */
export function fixed(x, digits) {
  const text = x.toFixed(digits);
  // toFixed(100) is the exact decimal expansion as far as a tie can reach (a double whose expansion
  // stops at digit digits + 1 has at most that many digits).
  const exact = Math.abs(x).toFixed(100);
  const dot = exact.indexOf('.');
  if (!/^50*$/.test(exact.slice(dot + 1 + digits))) return text;
  const truncated = (x < 0 ? '-' : '') + exact.slice(0, digits ? dot + 1 + digits : dot);
  return Number(truncated.slice(-1)) % 2 === 0 ? truncated : text;
}
