import { startShell } from '../common/shell2d.js';
startShell('slingshot', 'Slingshot');
