-- Configuration of the rapid language server for Neovim 0.11's vim.lsp.config
-- (found on 'runtimepath' as lsp/rapid.lua); enable it with vim.lsp.enable('rapid').
return {
  cmd = { 'rapid', 'lsp' },
  filetypes = { 'rapid' },
  -- a controller backup has BACKINFO, SYSPAR and RAPID; require('rapid')
  -- also takes a folder with a .pgf program as a root
  root_markers = { 'rapid.toml', 'EIO.cfg', 'eio.cfg', 'BACKINFO', 'SYSPAR', 'RAPID', '.git' },
  settings = {},
}
