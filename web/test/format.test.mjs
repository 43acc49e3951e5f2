// fixed() (web/src/format.js) against C's "%.4f", as `hbc table` prints Table 1's ratios; the
// oracle is Debian's Python, whose "%" formatting rounds the double's exact value half to even as
// glibc's printf does.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { fixed } from '../src/format.js';

test('fixed(x, 4) writes what printf("%.4f") writes, exact ties included', () => {
  // Ratios k/n of cell counts: exact ties such as 1/32 (0.03125) and 31/32 among them, 1 itself.
  const xs = [1, 0, 0.99, 0.9689119170984456];
  for (let n = 1; n <= 160; n++) for (let k = 0; k <= n; k++) xs.push(k / n);
  const want = execFileSync('/usr/bin/python3', ['-c', 'import sys\nfor l in sys.stdin: print("%.4f" % float(l))'],
    { input: xs.map((x) => String(x)).join('\n') + '\n', encoding: 'utf8' }).trim().split('\n');
  const got = xs.map((x) => fixed(x, 4));
  assert.deepEqual(got, want);
  assert.equal(fixed(1, 4), '1.0000');
  assert.equal(fixed(1 / 32, 4), '0.0312'); // toFixed gives 0.0313
});
