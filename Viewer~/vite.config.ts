import { defineConfig } from 'vitest/config';

// Relative asset paths, so the built viewer works from any folder and from `fulcrum view`.
export default defineConfig({
  base: './',
  build: { outDir: 'dist', emptyOutDir: true, chunkSizeWarningLimit: 1024 },
  test: { include: ['test/**/*.test.ts'] },
});
