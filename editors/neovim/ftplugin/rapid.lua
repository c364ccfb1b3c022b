-- RAPID buffers: comments start with '!'; tree-sitter highlighting when the
-- parser is built (see :RapidBuildParser).
vim.bo.commentstring = '! %s'
vim.bo.comments = ':!'
vim.b.undo_ftplugin = (vim.b.undo_ftplugin and (vim.b.undo_ftplugin .. ' | ') or '')
  .. 'setlocal commentstring< comments<'
require('rapid').attach(vim.api.nvim_get_current_buf())
