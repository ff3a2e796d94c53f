import { startShell } from '../common/shell2d.js';
startShell('scroller', 'Side-scroller');
