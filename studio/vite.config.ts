import { defineConfig } from "vite";
import react from "@vitejs/plugin-react";

// Fixed file names: fgplay embeds exactly index.html, assets/studio.js and assets/studio.css
// (runtime/studio/CMakeLists.txt), so nothing is looked up at run time.
export default defineConfig({
  plugins: [react()],
  base: "./",
  build: {
    target: "es2020",
    cssCodeSplit: false,
    assetsInlineLimit: 100000000,
    rollupOptions: {
      output: {
        entryFileNames: "assets/studio.js",
        chunkFileNames: "assets/studio-[name].js",
        assetFileNames: "assets/studio[extname]",
        inlineDynamicImports: true,
      },
    },
  },
  server: { proxy: { "/api": "http://127.0.0.1:8765" } },
});
